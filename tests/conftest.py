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
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci" if os.environ.get("CI") else "dev"))


# The fast lane (`make check`) leaves out what takes seconds per test and is covered by `make test`:
# notebooks, the browser, pdflatex, a fresh pip install, fuzzing, property tests that draw many
# random chains, and dhsym started as a process. `make test` runs everything.
SLOW_FILES = ("test_notebooks.py", "test_notebook_pages.py", "test_fuzz.py", "test_velocity_properties.py",
              "test_urdf_real.py", "test_inverse_random.py")
SLOW_TESTS = ("test_a_plain_pip_install_works_from_another_folder", "test_case_through_subprocess",
              "test_commands_without_pictures_import_no_numpy", "test_transform_times_its_inverse_is_identity",
              "test_every_frame_matches_the_raw_product_numerically",
              "test_the_ur5_determinant_factors_without_a_wrist_centre",
              "test_any_geometry_writes_a_robot_file_that_reads_back_with_its_kinematics",
              # test_cli.py's real processes (the rest of the file runs in process)
              "test_demo_output", "test_same_output_under_any_hash_seed", "test_a_full_disk_is_an_error_not_a_bug",
              "test_a_closed_standard_output_or_pipe_is_not_a_bug",
              "test_the_textbook_forms_print_unchanged_at_the_default_width")
SLOW_FIXTURES = ("compiled",)  # tests that run pdflatex


# Under pytest-xdist (`make test` runs `-n 2 --dist loadgroup`), the tests that share a costly
# module fixture run on one worker, so that it is built once: the compiled LaTeX documents of a
# file, and each notebook (executed once, then rendered in the browser from the same run).
SHARED_FIXTURES = ("compiled",)


def _xdist_group(item) -> str | None:
    fixtures = getattr(item, "fixturenames", ())
    shared = [name for name in SHARED_FIXTURES if name in fixtures]
    if shared:
        return f"{item.path.name}:{shared[0]}"
    if item.path.name in ("test_notebooks.py", "test_notebook_pages.py") and hasattr(item, "callspec"):
        path = item.callspec.params.get("path")
        return f"notebook:{path.name}" if path is not None else None
    return None


def pytest_collection_modifyitems(config, items):
    import pytest

    grouping = config.pluginmanager.hasplugin("xdist")
    for item in items:
        fixtures = getattr(item, "fixturenames", ())
        if (item.path.name in SLOW_FILES or getattr(item, "originalname", item.name) in SLOW_TESTS
                or any(name in fixtures for name in SLOW_FIXTURES)):
            item.add_marker(pytest.mark.slow)
        group = _xdist_group(item) if grouping else None
        if group:
            item.add_marker(pytest.mark.xdist_group(group))
