"""ttsgc: a declarative traffic-scenario compiler, from a sentence to validated OpenSCENARIO."""

__version__ = "0.1.0"
