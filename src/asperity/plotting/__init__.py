"""Matplotlib figures in the style of the seeds' figures, one module per analysis."""
