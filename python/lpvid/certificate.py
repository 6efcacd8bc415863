"""Certificates as objects: held in memory, saved, loaded and verified.

A certificate (format lpvid-certificate/1, docs/certificate_format.md)
names its data file(s) by path, relative to the certificate's folder, and
by SHA-256. A Certificate keeps the certificate's exact text and the bytes
of every data file it names, so it stays checkable after the folder of the
run that wrote it is gone: `save` writes both, `verify` rechecks them with
the verifier's exact arithmetic (lpvid-verify, in this process).
"""

import dataclasses
import json
import os
import re
from typing import Optional

from ._errors import LpvidError
from ._exact import exact
from ._run import run_captured
from ._workspace import read_bytes, workspace


def _data_entries(document):
    """The certificate's data references: the "data" object, or every
    entry of "records" (several records under one Delta)."""
    if isinstance(document.get("records"), list):
        return [e for e in document["records"] if isinstance(e, dict)]
    data = document.get("data")
    return [data] if isinstance(data, dict) else []


def _rewrite_file_references(text, renamed):
    """The certificate's text with the values of its "file" keys replaced
    as `renamed` says, and nothing else touched."""
    def replace(m):
        ref = json.loads(m.group(2))
        return m.group(1) + json.dumps(renamed.get(ref, ref), ensure_ascii=False)
    return re.sub(r'("file"\s*:\s*)("(?:[^"\\]|\\.)*")', replace, text)




@dataclasses.dataclass
class Verification:
    """What the verifier said of a certificate: ok (the claim holds, exit
    0) or not (exit 1, the reason in `output`). bool(v) is v.ok."""

    ok: bool
    code: int
    certificate: str
    data: Optional[str]
    output: str
    messages: str

    def __bool__(self):
        return self.ok


class Certificate(os.PathLike):
    """One certificate: `document` (the parsed JSON), `text` (its exact
    text), `files` (data file reference -> bytes) and `path` (where it is
    on disk, or None when it lives in memory only).

    os.fspath(cert) is its path once saved (so it can be passed wherever a
    certificate file is expected); an unsaved certificate raises TypeError
    there: call save(path) first.
    """

    def __init__(self, text, files=None, path=None):
        self.text = text
        try:
            self.document = json.loads(text)
        except ValueError as e:
            raise LpvidError(2, f"{path or 'certificate'}: not JSON: {e}") from None
        self.files = dict(files or {})
        self.path = None if path is None else os.path.abspath(os.fspath(path))

    # -- what it claims ---------------------------------------------------
    @property
    def claim(self):
        """"consistent", "invalidated", "lower_bound", ... (the "claim" field)."""
        return self.document.get("claim")

    @property
    def delta2(self):
        """The certified delta^2 as an exact Fraction (None if absent)."""
        return exact(self.document.get("delta2"))

    @property
    def dmax2(self):
        """The certified d_max^2 as an exact Fraction (None if absent)."""
        return exact(self.document.get("dmax2"))

    @property
    def model(self):
        """The model the claim is about (an lpvid-model/1 dict, everything identified folded in)."""
        from .model import Model
        m = self.document.get("model")
        return None if m is None else Model(m)

    def to_dict(self):
        return json.loads(self.text)

    def __repr__(self):
        where = self.path or "in memory"
        return f"<lpvid.Certificate claim={self.claim!r} ({where}, {len(self.files)} data file(s))>"

    def __fspath__(self):
        if self.path is None:
            raise TypeError("this certificate is in memory only: save(path) writes it (with its data files)")
        return self.path

    # -- files ---------------------------------------------------------------
    @classmethod
    def load(cls, path):
        """Reads a certificate file and the data file(s) it names (relative
        to its folder). A data file that is missing is left out: verify()
        then reports it."""
        path = os.path.abspath(os.fspath(path))
        try:
            text = read_bytes(path).decode("utf-8")
        except OSError as e:
            raise LpvidError(6 if os.path.exists(path) else 2, f"{path}: {e.strerror}") from None
        cert = cls(text, path=path)
        folder = os.path.dirname(path)
        for entry in _data_entries(cert.document):
            ref = entry.get("file")
            if isinstance(ref, str):
                full = ref if os.path.isabs(ref) else os.path.join(folder, ref)
                if os.path.isfile(full):
                    cert.files[ref] = read_bytes(full)
        return cert

    def save(self, path):
        """Writes the certificate to `path` and its data file(s) beside it
        (by their base names). Only the "file" references change, in the text
        itself: every number keeps its exact text (a JSON round trip through
        floats could change a certified number), and a data file is identified
        by its SHA-256. Returns the path; the Certificate then refers to it."""
        path = os.path.abspath(os.fspath(path))
        folder = os.path.dirname(path)
        os.makedirs(folder, exist_ok=True)
        renamed, files = {}, {}
        for k, entry in enumerate(_data_entries(self.document)):
            ref = entry.get("file")
            if ref not in self.files:
                raise LpvidError(2, f"certificate: the bytes of its data file {ref!r} are not held; load it "
                                    "from a folder that has the file")
            name = os.path.basename(ref)
            if name in files and files[name] != self.files[ref]:
                stem, ext = os.path.splitext(name)
                name = f"{stem}.{k + 1}{ext}"
            renamed[ref], files[name] = name, self.files[ref]
        for name, data in files.items():
            with open(os.path.join(folder, name), "wb") as f:
                f.write(data)
        text = _rewrite_file_references(self.text, renamed)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        self.text, self.document, self.path = text, json.loads(text), path
        self.files = files
        return path

    def verify(self, data=None, **options):
        """Rechecks the claim exactly (see lpvid.verify)."""
        return verify(self, data=data, **options)


def verify(certificate, data=None, *, progress=None, **options):
    """Checks a certificate exactly (`lpvid-verify certificate`), from the
    data file's bytes to the PSD decision, with no tolerance.

    certificate: a Certificate (from a result, or Certificate.load) or a
    certificate file's path. data: the data file to read instead of the
    recorded one (its SHA-256 must still match). options: the verifier's
    limits (max_file_mb=..., max_digits=...). Returns a Verification, true
    when the claim holds (exit 0), false when it does not (exit 1); a
    missing, malformed or unreadable certificate or data file (exit 2, 6)
    raises LpvidError. An in-memory certificate is written with its data
    files into a private folder for the check and the folder removed.
    """
    from ._options import check, option_words
    check("verify", "lpvid-verify", options, managed=("data",))
    if isinstance(certificate, Certificate) and (certificate.path is None or not os.path.isfile(certificate.path)):
        with workspace("verify") as folder:
            copy = Certificate(certificate.text, certificate.files)
            path = copy.save(os.path.join(folder, "certificate.json"))
            return _verify_file(path, data, options, option_words, progress, shown=repr(certificate))
    path = os.fspath(certificate)
    return _verify_file(path, data, options, option_words, progress, shown=path)


def _verify_file(path, data, options, option_words, progress, shown):
    args = ["certificate", path]
    if data is not None:
        args += ["--data", os.fspath(data)]
    args += option_words(options)
    code, output, messages = run_captured("lpvid-verify", args, progress)
    if code not in (0, 1):
        from ._invoke import raise_error  # late: _invoke imports the modules that import this one
        raise_error(code, output, messages, {"args": args, "options": options, "sources": {}})
    return Verification(ok=code == 0, code=code, certificate=shown, data=None if data is None else os.fspath(data),
                        output=output, messages=messages)
