"""Readers of text exports: the data block and header (:mod:`.text`), what the columns and
header keys mean (:mod:`.layout`), length units as instruments spell them (:mod:`.units`)."""
