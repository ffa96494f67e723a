import os
import sys

from hypothesis import HealthCheck, settings

sys.path.insert(0, os.path.dirname(__file__))  # for tests/textbook.py, tests/cli_runner.py

# No deadlines and no too-slow health check: a shared 2-core machine is slow at times, and speed
# is measured in benchmarks/. Locally each run explores new examples; CI draws the same ones each
# time (derandomize), so that a red build is reproducible and means a change, not a dice roll.
settings.register_profile("dev", deadline=None, max_examples=40, suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("ci", deadline=None, max_examples=40, suppress_health_check=[HealthCheck.too_slow],
                          derandomize=True)
# `make check` (the edit-test loop) draws 10 examples per property; `make test` the profile's 40.
settings.register_profile("quick", deadline=None, max_examples=10, suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci" if os.environ.get("CI") else "dev"))


# The fast lane (`make check`, `-m "not slow"`) leaves out what takes seconds per test and is covered by
# `make test`: each such test is marked where it is defined (`@pytest.mark.slow`, or a file's
# `pytestmark` for notebooks, the browser, fuzzing, property tests drawing many random chains and real
# robots solved in closed form). No list of names here: a renamed test keeps its mark.
