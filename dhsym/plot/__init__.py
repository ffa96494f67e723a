"""Pictures of chains and the numbers behind them: `draw`, `draw_closed`, `save`, numeric
`frame_poses`, and `close_loop` for mechanisms cut into serial chains.

Importing this package imports numpy and matplotlib; nothing outside it needs them.

>>> import dhsym
>>> ax = dhsym.plot.draw(dhsym.load("planar2r"), {"theta_1": "30deg", "theta_2": "45deg"})
>>> ax.get_title().splitlines()[0]
'Planar elbow manipulator (2R)'
"""
from .draw import draw, draw_closed, picture_format, save
from .loops import close_loop
from .poses import frame_poses, is_planar, resolve_values

__all__ = ["close_loop", "draw", "draw_closed", "frame_poses", "is_planar", "picture_format", "resolve_values",
           "save"]
