"""The package's version (ground floor: the manifest and the study record it without importing the package
root, whose lazy re-exports reach the top of the house)."""

__version__ = "0.1.0"
