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


# The fast lane (`make check`) leaves out what takes seconds per test and is covered by `make test`:
# notebooks, the browser, pdflatex, a fresh pip install, fuzzing, property tests that draw many
# random chains, and dhsym started as a process. `make test` runs everything.
SLOW_FILES = ("test_notebooks.py", "test_notebook_pages.py", "test_web_page.py", "test_extras.py", "test_fuzz.py",
              "test_velocity_properties.py", "test_urdf_real.py", "test_inverse_random.py",
              "test_simplify_equals_raw.py",
              # real robots solved in closed form (the fast lane keeps test_ik_cli's hand-written solutions,
              # the subproblems and dhsym.inverse's doctests)
              "test_inverse_robots.py", "test_ik_solved.py", "test_ik_text.py")
SLOW_TESTS = ("test_a_plain_pip_install_works_from_another_folder", "test_case_through_subprocess",
              "test_commands_without_pictures_import_no_numpy", "test_transform_times_its_inverse_is_identity",
              "test_every_frame_matches_the_raw_product_numerically",
              "test_the_ur5_determinant_factors_without_a_wrist_centre",
              "test_any_geometry_writes_a_robot_file_that_reads_back_with_its_kinematics",
              "test_any_mix_of_value_kinds_reads_back", "test_random_axes_to_table_keep_the_kinematics",
              "test_random_tables_through_their_axes_reproduce_the_kinematics",
              # seconds of SymPy each: determinants, the PUMA's eight branches, 3,000 tool steps, a macro bomb
              "test_json_reads_back_and_has_the_documented_keys",
              "test_a_factored_determinant_keeps_the_decimals_as_written",
              "test_the_ur5_determinant_does_not_depend_on_the_machine",
              "test_whether_a_determinant_is_factored_is_decided_by_counting_terms",
              "test_an_offset_wrist_arm_has_the_same_determinant_in_both_conventions",
              "test_the_determinant_of_a_general_three_link_arm_is_its_linear_block",
              "test_puma_json_and_module_reach_random_poses_with_all_eight_branches",
              "test_documents_with_the_derivation_compile_and_fit", "test_too_many_yaml_values_are_refused",
              "test_every_robot_command_reads_the_robot_file_from_standard_input",
              "test_case_in_process[xacro_doubling_macro]", "test_case_in_process[cli_fk_3000_tool_steps]",
              "test_every_frame_is_the_exact_product_evaluated", "test_the_end_pose_is_the_forward_kinematics",
              "test_json_reads_back_equal_to_the_exact_solution",
              "test_text_latex_and_python_write_the_decimals_of_the_file",
              "test_evaluate_is_the_generated_module_with_nan_where_a_branch_does_not_exist",
              "test_check_and_too_large_advice_use_the_printed_numbers",
              # dhsym started as a real process (the rest of these files runs in process)
              "test_demo_output", "test_same_output_under_any_hash_seed", "test_a_full_disk_is_an_error_not_a_bug",
              "test_a_signal_during_an_output_write_leaves_no_temporary_file",
              "test_a_closed_standard_output_or_pipe_is_not_a_bug",
              "test_the_textbook_forms_print_unchanged_at_the_default_width",
              "test_an_ascii_terminal_gets_advice_not_a_traceback",
              "test_a_named_pipe_nobody_writes_is_refused_at_once_not_waited_for",
              "test_a_named_pipe_nobody_reads_is_refused_as_output_and_no_file_appears",
              "test_a_socket_is_neither_a_robot_file_nor_an_output", "test_devices_and_standard_input_still_work",
              "test_the_page_imports_nothing_the_browser_lacks")
SLOW_FIXTURES = ("compiled",)  # tests that run pdflatex


def pytest_collection_modifyitems(config, items):
    import pytest

    for item in items:
        fixtures = getattr(item, "fixturenames", ())
        if (item.path.name in SLOW_FILES or item.name in SLOW_TESTS
                or getattr(item, "originalname", item.name) in SLOW_TESTS
                or any(name in fixtures for name in SLOW_FIXTURES)):
            item.add_marker(pytest.mark.slow)
