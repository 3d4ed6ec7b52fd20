"""rollerrig: real-time simulation of a scaled railway roller rig."""
from ._version import __version__

__all__ = ["__version__"]
