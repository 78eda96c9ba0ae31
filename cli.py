"""The realsim command line, run from a checkout: ``python cli.py convert ...``.

The implementation is :mod:`realsim.cli`, installed inside the package as the ``realsim``
command (never as a bare top-level ``cli`` module that could clash with another package's).
"""

from realsim.cli import main

if __name__ == "__main__":
    raise SystemExit(main())
