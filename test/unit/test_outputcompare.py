"""The example comparator must fail on a value changed beyond tolerance and pass within it."""
import os
import sys
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
import outputcompare  # noqa: E402

# A sample in the shape of example output: integers, reals in several formats, words with digits.
SAMPLE = """step    0  particles 324  contacts 0  KE 0.000000000000e+00 J  mean height 4.19879702478257e-03 m
step  250  particles 324  contacts 21  KE 6.297188407759e-07 J  mean height 4.17917685007432e-03 m
e 0.3: measured 0.299346, error 0.218 % (tolerance 2 %) ok
weight of all particles 3.32845458e-02 N, load on the floor 3.32845458e-02 N
"""


class CompareTest(unittest.TestCase):
    def setUp(self):
        self.ref = SAMPLE

    def test_identical_passes(self):
        self.assertTrue(outputcompare.compare(self.ref, self.ref, 1e-9, 1e-14)[0])

    def test_float_within_tolerance_passes(self):
        changed = self.ref.replace("3.32845458e-02 N, load", "3.32845458000001e-02 N, load")
        self.assertNotEqual(changed, self.ref)
        self.assertTrue(outputcompare.compare(self.ref, changed, 1e-9, 1e-14)[0])

    def test_float_beyond_tolerance_fails(self):
        changed = self.ref.replace("3.32845458e-02 N, load", "3.32845558e-02 N, load")
        self.assertNotEqual(changed, self.ref)
        ok, report = outputcompare.compare(self.ref, changed, 1e-9, 1e-14)
        self.assertFalse(ok)
        self.assertIn("3.32845558e-02", report)
        self.assertIn("+weight", report)  # the unified diff

    def test_changed_integer_fails(self):
        changed = self.ref.replace("contacts 21", "contacts 22", 1)
        self.assertFalse(outputcompare.compare(self.ref, changed, 1.0, 1.0)[0])

    def test_changed_text_and_missing_line_fail(self):
        self.assertFalse(outputcompare.compare(self.ref, self.ref.replace("on the floor", "on the roof"))[0])
        self.assertFalse(outputcompare.compare(self.ref, "\n".join(self.ref.splitlines()[:-1]))[0])

    def test_words_with_digits_are_text(self):
        self.assertFalse(outputcompare.compare("ex01 ok", "ex02 ok", 1.0, 1.0)[0])
        self.assertEqual(outputcompare.tokenize("x2 = 3.5")[0], ("text", "x2 = "))

    def test_integer_against_float_uses_tolerance(self):
        self.assertTrue(outputcompare.compare("KE 0 J", "KE 1e-20 J", 1e-9, 1e-14)[0])
        self.assertFalse(outputcompare.compare("KE 0 J", "KE 1e-3 J", 1e-9, 1e-14)[0])


if __name__ == "__main__":
    unittest.main()
