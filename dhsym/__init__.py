"""dhsym: Denavit–Hartenberg tables to textbook-form symbolic kinematics."""
from .chain import Chain, DHRow
from .errors import Location, UserError
from .expr import parse_expression, real_symbol
from .transforms import Step

__all__ = ["Chain", "DHRow", "Location", "Step", "UserError", "parse_expression", "real_symbol"]
