"""Runs one unittest module for ctest: exit 0 when its tests pass, 1 when one fails, and 77 (ctest's
SKIP_RETURN_CODE here) when every test of the module was skipped, so ctest reports it as skipped
rather than passed (e.g. the tests of the real scans when ../shared/data is absent).

Usage: python3 run_unittest.py MODULE
"""
import sys
import unittest

SKIPPED = 77

suite = unittest.defaultTestLoader.loadTestsFromName(sys.argv[1])
result = unittest.TextTestRunner(verbosity=2).run(suite)
if not result.wasSuccessful():
    sys.exit(1)
if result.testsRun > 0 and len(result.skipped) == result.testsRun:
    print("every test of %s skipped" % sys.argv[1])
    sys.exit(SKIPPED)
sys.exit(0)
