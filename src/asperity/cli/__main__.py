"""``python -m asperity.cli``: the same as the ``asperity`` command."""

from . import main

main()
