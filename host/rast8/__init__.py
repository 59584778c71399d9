"""rast8 host tools: decode, view and analyse rast8 serial frame streams."""
__version__ = "0.1.0"
