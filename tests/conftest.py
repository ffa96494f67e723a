import os
import sys

from hypothesis import HealthCheck, settings

sys.path.insert(0, os.path.dirname(__file__))  # for tests/textbook.py

# No deadlines and no too-slow health check: a shared 2-core machine is slow at times, and speed
# is measured in benchmarks/. Locally each run explores new examples; CI draws the same ones each
# time (derandomize), so that a red build is reproducible and means a change, not a dice roll.
settings.register_profile("dev", deadline=None, max_examples=40, suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("ci", deadline=None, max_examples=40, suppress_health_check=[HealthCheck.too_slow],
                          derandomize=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci" if os.environ.get("CI") else "dev"))
