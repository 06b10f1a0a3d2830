"""THE geometry kernel of sovarc, shared by lowering, synthesis and every oracle.

- angles.py: compass degrees (0 = north, clockwise); angle_diff(a, b) = signed a - b in (-180, 180].
- polyline.py: Polyline (arc length, projection, offsets, smoothing) and helpers on plain shapes.
- frame.py: the road frame (s, d) across a road, `Band`.
- bodies.py: the oriented body box `Box` with ONE touching rule (touching is not overlapping),
  its overlap, and the first touch of two moving boxes (`Contact`).
- lanes.py: a network's lanes as shapes (`LaneMap`): which lane a point is on, heading which way.
- lane_lines.py: THE lane-line test (a body over a painted line into a lane its route may not use).
"""

from sovarc.compiler.geometry.angles import angle_diff, angle_diffs, circular_mean, compass, heading_vector
from sovarc.compiler.geometry.bodies import Box, Contact, between, closest_points, first_touch, overlap
from sovarc.compiler.geometry.frame import Band
from sovarc.compiler.geometry.polyline import Point, Polyline, bezier, blend, concat

__all__ = [
    "Band",
    "Box",
    "Contact",
    "Point",
    "Polyline",
    "angle_diff",
    "angle_diffs",
    "between",
    "bezier",
    "blend",
    "circular_mean",
    "closest_points",
    "compass",
    "concat",
    "first_touch",
    "heading_vector",
    "overlap",
]
