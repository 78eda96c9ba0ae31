"""realsim: turn a captured real scene into a settled MuJoCo simulation."""

__version__ = "0.1.0"
