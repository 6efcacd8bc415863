"""The folder a call works in: private and removed afterwards, or the
caller's out_dir, kept.

A run of lpvid reads and writes files (the data as CSV, the model, the
report, certificates, plot tables). Unless the caller names a folder
(out_dir=), they go into a new temporary folder that is removed when the
call returns, fails or is interrupted: everything a result needs (numbers,
arrays, the model, certificates with their data files' bytes) is read into
memory first.
"""

import contextlib
import os
import shutil
import tempfile


@contextlib.contextmanager
def workspace(command, out_dir=None):
    """Yields the absolute path of the folder to work in."""
    if out_dir is not None:
        path = os.path.abspath(os.fspath(out_dir))
        os.makedirs(path, exist_ok=True)
        yield path
        return
    path = tempfile.mkdtemp(prefix=f"lpvid-{command}-")
    try:
        yield path
    finally:
        shutil.rmtree(path, ignore_errors=True)


def read_bytes(path):
    with open(path, "rb") as f:
        return f.read()
