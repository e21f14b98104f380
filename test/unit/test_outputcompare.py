"""The example comparator must fail on a value changed beyond tolerance and pass within it."""
import os
import sys
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
import outputcompare  # noqa: E402

REF = os.path.join(ROOT, "examples", "output", "ex01_box_drop_1.out")


class CompareTest(unittest.TestCase):
    def setUp(self):
        with open(REF) as f:
            self.ref = f.read()

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
        changed = self.ref.replace("particles 324", "particles 323", 1)
        self.assertFalse(outputcompare.compare(self.ref, changed, 1.0, 1.0)[0])

    def test_changed_text_and_missing_line_fail(self):
        self.assertFalse(outputcompare.compare(self.ref, self.ref.replace("floor force", "floor torque"))[0])
        self.assertFalse(outputcompare.compare(self.ref, "\n".join(self.ref.splitlines()[:-1]))[0])

    def test_words_with_digits_are_text(self):
        self.assertFalse(outputcompare.compare("ex01 ok", "ex02 ok", 1.0, 1.0)[0])
        self.assertEqual(outputcompare.tokenize("x2 = 3.5")[0], ("text", "x2 = "))

    def test_integer_against_float_uses_tolerance(self):
        self.assertTrue(outputcompare.compare("KE 0 J", "KE 1e-20 J", 1e-9, 1e-14)[0])
        self.assertFalse(outputcompare.compare("KE 0 J", "KE 1e-3 J", 1e-9, 1e-14)[0])


if __name__ == "__main__":
    unittest.main()
