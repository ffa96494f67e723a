import os
import sys

from hypothesis import settings

sys.path.insert(0, os.path.dirname(__file__))  # for tests/textbook.py

settings.register_profile("dev", deadline=None, max_examples=40)
settings.register_profile("ci", deadline=None, max_examples=40)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci" if os.environ.get("CI") else "dev"))
