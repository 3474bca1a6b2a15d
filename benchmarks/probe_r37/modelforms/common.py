"""Shared helpers: asserts the snapshot under test."""
import sys
sys.path.insert(0, "/tmp/r37/src")
import critmoment  # noqa: E402
assert critmoment.__file__.startswith("/tmp/r37/src"), critmoment.__file__
