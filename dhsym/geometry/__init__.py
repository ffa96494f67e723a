"""From a robot's geometry to its DH table and back: joint axes as lines, the frame-assignment
algorithm (standard and modified), conversion between conventions, screw axes and a table checker
(URDF reading is in io). It builds on core only (io's robot files use it for the `axes:` form)."""
