"""The numeric inverse kinematics' working code, numpy only and free of dhsym: the chain in numbers
(`chain`), the elimination to one polynomial solved as an eigenvalue problem (`elimination`) and
every solution at many poses (`solve`). `dhsym ik --format python` copies these files' text into
the module it writes for an arm solved numerically (dhsym.inverse.numeric.codegen), so that the
module and `dhsym.inverse.numeric` compute the same numbers.
"""
