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


# The fast lane (`make check`) leaves out what takes minutes: notebooks, the browser, pdflatex,
# a fresh pip install, fuzzing, property tests and dhsym run as a process. `make test` runs everything.
# The CLI files run dhsym as a process per case; the property files draw many random chains.
SLOW_FILES = ("test_notebooks.py", "test_notebook_pages.py", "test_fuzz.py", "test_cli.py", "test_velocity_cli.py",
              "test_readme.py", "test_velocity_properties.py", "test_urdf_real.py", "test_inverse_random.py")
SLOW_TESTS = ("test_a_plain_pip_install_works_from_another_folder", "test_case_through_subprocess",
              "test_commands_without_pictures_import_no_numpy", "test_transform_times_its_inverse_is_identity",
              "test_every_frame_matches_the_raw_product_numerically",
              "test_the_ur5_determinant_factors_without_a_wrist_centre",
              "test_any_geometry_writes_a_robot_file_that_reads_back_with_its_kinematics")
SLOW_FIXTURES = ("compiled",)  # tests that run pdflatex


def pytest_collection_modifyitems(config, items):
    import pytest

    for item in items:
        fixtures = getattr(item, "fixturenames", ())
        if (item.path.name in SLOW_FILES or getattr(item, "originalname", item.name) in SLOW_TESTS
                or any(name in fixtures for name in SLOW_FIXTURES)):
            item.add_marker(pytest.mark.slow)
