"""The checked readers: good files load, damaged ones raise DataError naming the file and problem."""
import math
import tempfile
import unittest
from pathlib import Path

import fixtures
from relslam_data import DataError, read_csv, read_json, read_tum


class ReaderTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.folder = Path(self.dir.name)

    def tearDown(self):
        self.dir.cleanup()

    def file(self, name, text):
        return fixtures.write(self.folder, {name: text}) / name

    def assertDataError(self, call, path, problem):
        """The error names the file and says what is wrong with it."""
        with self.assertRaises(DataError) as caught:
            call()
        self.assertEqual(caught.exception.path, Path(path))
        self.assertIn(problem, str(caught.exception))
        self.assertTrue(str(caught.exception).startswith(str(path)))


class ReadCsvTest(ReaderTest):
    def test_reads_numbers_text_and_empty_fields(self):
        frame = read_csv(self.file("a.csv", "x,level,e\n1,final,\n2,None,nan\n"), required=("x",), numeric=("x", "e"))
        self.assertEqual(list(frame["x"]), [1, 2])
        self.assertEqual(list(frame["level"]), ["final", "None"])  # a label, not a missing value
        self.assertTrue(frame["e"].isna().all())

    def test_missing_file(self):
        path = self.folder / "none.csv"
        self.assertDataError(lambda: read_csv(path), path, "file not found")

    def test_cut_file(self):
        path = self.file("cut.csv", "x,y\n1,2\n3,")
        self.assertDataError(lambda: read_csv(path), path, "cut short")

    def test_short_row(self):
        path = self.file("short.csv", "x,y,z\n1,2,3\n4,5\n")
        self.assertDataError(lambda: read_csv(path), path, "line 3: 2 fields, the header has 3")

    def test_empty_file(self):
        path = self.file("empty.csv", "")
        self.assertDataError(lambda: read_csv(path), path, "empty file")

    def test_missing_column(self):
        path = self.file("a.csv", "x,y\n1,2\n")
        self.assertDataError(lambda: read_csv(path, required=("x", "runtime_ms")), path, "missing column(s) runtime_ms")

    def test_not_a_number(self):
        path = self.file("a.csv", "x,y\n1,2\noops,3\n")
        self.assertDataError(lambda: read_csv(path, numeric=("x",)), path, "line 3: column x: not a number: 'oops'")

    def test_numeric_test_on_names(self):
        path = self.file("a.csv", "a_ci95,b\n1,text\n")
        self.assertEqual(read_csv(path, numeric=lambda c: c.endswith("_ci95"))["a_ci95"][0], 1)


class ReadTumTest(ReaderTest):
    def test_reads_columns_and_skips_comments(self):
        frame = read_tum(self.file("t.tum", "# t x y z qx qy qz qw\n" + fixtures.TRAJECTORY))
        self.assertEqual(list(frame.columns), ["t", "x", "y", "z", "qx", "qy", "qz", "qw"])
        self.assertEqual(len(frame), 3)
        self.assertTrue(math.isclose(frame["z"].iloc[-1], 0.6))

    def test_wrong_field_count(self):
        path = self.file("t.tum", "0 0 0 0 0 0 0 1\n1 2 3\n")
        self.assertDataError(lambda: read_tum(path), path, "line 2: 3 fields")

    def test_not_a_number(self):
        path = self.file("t.tum", "0 0 0 x 0 0 0 1\n")
        self.assertDataError(lambda: read_tum(path), path, "line 1: not a number")


class ReadJsonTest(ReaderTest):
    def test_invalid_json(self):
        path = self.file("manifest.json", "{\"a\": \n")
        self.assertDataError(lambda: read_json(path), path, "not valid JSON")

    def test_reads_json(self):
        self.assertEqual(read_json(self.file("plan.json", "{\"a\": 1}\n")), {"a": 1})


if __name__ == "__main__":
    unittest.main()
