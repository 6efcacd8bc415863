#!/usr/bin/env python3
"""A second, independent checker of lpvid certificates (format lpvid-certificate/1).

Written from the documentation only (docs/certificates.md, docs/certificate_format.md,
docs/certificate.schema.json, docs/dual_certificates.md, docs/class_lower_bound.md,
docs/several_records.md, docs/model.schema.json, docs/design.md), in Python's standard
library and exact fractions; where those pages are silent on the model's simulation (the
additive channel driven by the delayed, mapped input u', the uncertainty channel taken before
the output map, the 2^-32 grid of state scheduling) the header comments of src/model were read,
never its code. It shares no code with lpvid-verify: the point is a second route to the same
verdicts, so that a bug in one of them shows up as a disagreement.

It is meant for SMALL certificates (tens of samples): every matrix is built densely and
every PSD decision is a fraction-free elimination on integers.

Usage:  python3 exact_checker.py CERT.json [--data FILE]
Prints  "holds: ..."        exit 0   the claim holds exactly
        "refused: ..."      exit 1   the claim does not hold, or the file is not a valid certificate
        "unsupported: ..."  exit 3   the certificate uses something this checker does not decide

The mathematics (paper: "Robust identification and invalidation of LPV systems"):
  consistent / not_a_witness   Theorem 2.1, the two LMIs of eq. 7 ((C1) and (C2)), in the
                               Delta form (taps of a causal FIR Delta) or the w form;
  invalidated / lower_bound    a dual point of the full-horizon Delta form (Lagrangian of the
                               two LMIs), dense (dual_delta) or as a central-path recipe
                               (dual_delta_path) that is expanded here; or in closed form:
                               zero_delta (delta^2 = 0 forces w = 0, so d = r) and
                               nonnegative (a lower end <= 0);
  class_*                      Theorem 3.1 (eq. 11-12) over a box of corrections: one dual point
                               per leaf of a region tree, with the bilinear term bounded.
"""

import csv
import hashlib
import json
import math
import os
import re
import sys
from decimal import Decimal, getcontext, ROUND_HALF_EVEN
from fractions import Fraction

F0 = Fraction(0)
F1 = Fraction(1)

# Exact numbers of thousands of digits are ordinary here (an exact ||r||^2/(n*ny) of a record of a
# few hundred samples has some 13 000): lift Python's limit on int <-> text (4300 digits) to the
# 50 000 digits that lpvid's readers accept by default (--max-digits).
if hasattr(sys, 'set_int_max_str_digits'):
    sys.set_int_max_str_digits(50000)


class Refused(Exception):
    """The claim does not hold, or the certificate is malformed."""


class Unsupported(Exception):
    """The certificate uses a feature this checker does not decide."""


# ----------------------------------------------------------------------------------------
# Exact numbers and JSON
# ----------------------------------------------------------------------------------------

_DECIMAL = re.compile(r'^\s*([+-]?)(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\s*$')
_RATIO = re.compile(r'^\s*([+-]?\d+)\s*/\s*([+-]?\d+)\s*$')


def parse_decimal_text(text, what):
    """Exact value of a decimal text such as '-2.5e-3' ('0.1' is 1/10, never a double)."""
    m = _DECIMAL.match(text)
    if not m:
        raise Refused(f"{what}: '{text}' is not an exact decimal")
    if m.group(3) and abs(int(m.group(3)[1:])) > 4000:
        raise Refused(f"{what}: exponent of '{text}' is out of range")
    mant = m.group(2)
    if '.' in mant:
        whole, frac = mant.split('.')
    else:
        whole, frac = mant, ''
    value = Fraction(int((whole or '0') + frac), 10 ** len(frac))
    if m.group(3):
        e = int(m.group(3)[1:])
        value *= Fraction(10) ** e
    return -value if m.group(1) == '-' else value


def parse_number(v, what):
    """An exact number of the certificate: JSON number (kept as its text) or string."""
    if isinstance(v, bool) or v is None:
        raise Refused(f"{what}: expected a number")
    if isinstance(v, int):
        return Fraction(v)
    if isinstance(v, Fraction):
        return v
    if isinstance(v, str):
        m = _RATIO.match(v)
        if m:
            q = int(m.group(2))
            if q == 0:
                raise Refused(f"{what}: zero denominator in '{v}'")
            return Fraction(int(m.group(1)), q)
        return parse_decimal_text(v, what)
    raise Refused(f"{what}: expected a number, got {type(v).__name__}")


def _no_duplicates(pairs):
    out = {}
    for k, v in pairs:
        if k in out:
            raise Refused(f"duplicate key '{k}'")
        out[k] = v
    return out


def _bad_constant(name):
    raise Refused(f"'{name}' is not an exact number")


def load_json_exact(text):
    """JSON with every non-integer number kept exact (parse_float gets the text)."""
    return json.loads(text, parse_float=lambda s: parse_decimal_text(s, 'JSON number'),
                      parse_constant=_bad_constant, object_pairs_hook=_no_duplicates)


def num_matrix(rows, nrows, ncols, what):
    if rows == [] and (nrows == 0 or ncols == 0):
        return [[F0] * ncols for _ in range(nrows)]
    if not isinstance(rows, list) or len(rows) != nrows:
        raise Refused(f"{what}: expected {nrows} rows")
    out = []
    for i, row in enumerate(rows):
        if not isinstance(row, list) or len(row) != ncols:
            raise Refused(f"{what}: row {i} must have {ncols} entries")
        out.append([parse_number(x, what) for x in row])
    return out


def num_vector(v, n, what):
    if not isinstance(v, list) or len(v) != n:
        raise Refused(f"{what}: expected {n} numbers")
    return [parse_number(x, what) for x in v]


def check_keys(obj, allowed, what):
    if not isinstance(obj, dict):
        raise Refused(f"{what} must be an object")
    extra = set(obj) - set(allowed)
    if extra:
        raise Refused(f"{what}: unknown key(s) {sorted(extra)}")


# ----------------------------------------------------------------------------------------
# Small exact linear algebra (lists of Fractions / ints)
# ----------------------------------------------------------------------------------------

def zeros(r, c):
    return [[F0] * c for _ in range(r)]


def transpose(a):
    return [list(col) for col in zip(*a)] if a else []


def matmul(a, b):
    bt = transpose(b)
    return [[sum(x * y for x, y in zip(row, col)) for col in bt] for row in a]


def matvec(a, v):
    return [sum(x * y for x, y in zip(row, v)) for row in a]


def common_denominator(values):
    d = 1
    for v in values:
        q = v.denominator
        d = d * q // math.gcd(d, q)
    return d


def integer_scaled(m):
    """The symmetric rational matrix times a positive common denominator, as ints."""
    d = common_denominator(x for row in m for x in row)
    return [[int(x * d) for x in row] for row in m]


def is_psd_integer(a):
    """Exact PSD test of a symmetric integer matrix (destroys a): fraction-free symmetric
    elimination (Bareiss) with diagonal pivoting. After k steps every remaining entry is
    (product of the pivots taken) x (the Schur complement's entry), with positive pivots, so
    signs are those of the Schur complement. A negative diagonal entry refutes PSD; when no
    positive diagonal entry remains, PSD needs the rest to be all zero (a PSD matrix with a
    zero diagonal entry has that row zero). Returns (verdict, reason)."""
    n = len(a)
    for i in range(n):
        for j in range(i):
            if a[i][j] != a[j][i]:
                return False, "matrix is not symmetric"
    active = list(range(n))
    prev = 1
    step = 0
    while active:
        diag = [(a[i][i], i) for i in active]
        neg = [i for v, i in diag if v < 0]
        if neg:
            return False, f"negative pivot after {step} elimination steps"
        best, p = max(diag)
        if best == 0:
            for i in active:
                for j in active:
                    if a[i][j] != 0:
                        return False, f"zero pivot with a non-zero row after {step} steps"
            return True, f"PSD (rank {step} of {n})"
        active.remove(p)
        rowp = a[p]
        for i in active:
            ai = a[i]
            aip = ai[p]
            if aip == 0:
                for j in active:
                    ai[j] = ai[j] * best // prev
            else:
                for j in active:
                    ai[j] = (ai[j] * best - aip * rowp[j]) // prev
        prev = best
        step += 1
    return True, f"PD (rank {n})"


def is_psd_rational(m):
    return is_psd_integer(integer_scaled(m))


def column_space_projector_apply(cols, g):
    """g minus its orthogonal projection onto span(cols) (exact; dependent columns allowed)."""
    if not cols:
        return list(g)
    # Gram-Schmidt without normalisation (exact): orthogonal basis of the span.
    basis = []
    for c in cols:
        v = list(c)
        for b, bb in basis:
            coef = sum(x * y for x, y in zip(v, b)) / bb
            if coef:
                v = [x - coef * y for x, y in zip(v, b)]
        vv = sum(x * x for x in v)
        if vv != 0:
            basis.append((v, vv))
    out = list(g)
    for b, bb in basis:
        coef = sum(x * y for x, y in zip(out, b)) / bb
        if coef:
            out = [x - coef * y for x, y in zip(out, b)]
    return out


def sqrt_upper(x):
    """A rational s >= sqrt(x) >= 0, within about 2^-80 relative."""
    if x < 0:
        raise ValueError("negative")
    if x == 0:
        return F0
    p, q = x.numerator, x.denominator
    b = max(0, 90 - (p.bit_length() - q.bit_length()) // 2)
    y_num = p * 4 ** b
    a = math.isqrt(y_num // q)
    if Fraction(a * a) != Fraction(y_num, q):
        a += 1
    return Fraction(a, 2 ** b)


# ----------------------------------------------------------------------------------------
# The model (docs/design.md section 5, docs/model.schema.json)
# ----------------------------------------------------------------------------------------

_NAME = re.compile(r'^[A-Za-z_][A-Za-z0-9_]*$')


def parse_monomial(text, names):
    """'1', 'rho1', 'rho1^2*rho2' -> tuple of powers in the order of names."""
    if not isinstance(text, str):
        raise Refused("a basis function must be a string")
    powers = [0] * len(names)
    if text.strip() == '1':
        return tuple(powers)
    for factor in text.split('*'):
        f = factor.strip()
        m = re.match(r'^([A-Za-z_][A-Za-z0-9_]*)\s*(?:\^\s*(\d+))?$', f)
        if not m:
            raise Refused(f"basis function '{text}' does not parse")
        if m.group(1) not in names:
            raise Refused(f"basis function '{text}' names an undeclared variable")
        k = int(m.group(2)) if m.group(2) is not None else 1
        if k < 1 or k > 16:
            raise Refused(f"basis function '{text}': power out of range")
        powers[names.index(m.group(1))] += k
    if max(powers) > 16:
        raise Refused(f"basis function '{text}': power above 16")
    return tuple(powers)


def eval_monomial(powers, rho):
    v = F1
    for r, k in zip(rho, powers):
        if k:
            v *= r ** k
    return v


def parse_terms(lst, names, rows, cols, what, allowed_basis=None):
    if lst is None:
        return []
    if not isinstance(lst, list):
        raise Refused(f"{what} must be a list of terms")
    out = []
    seen = set()
    for t in lst:
        check_keys(t, ('basis', 'value'), f"{what} term")
        if 'basis' not in t or 'value' not in t:
            raise Refused(f"{what} term needs basis and value")
        mono = parse_monomial(t['basis'], names)
        if allowed_basis is not None:
            if mono not in allowed_basis:
                raise Refused(f"{what}: basis '{t['basis']}' is not a correction basis function")
            if mono in seen:
                raise Refused(f"{what}: two terms for one correction function")
            seen.add(mono)
        val = t['value']
        if val == [] or (rows > 0 and cols == 0 and val == [[]] * rows):
            continue
        out.append((mono, num_matrix(val, rows, cols, what)))
    return out


def eval_terms(terms, rho, rows, cols):
    m = [[F0] * cols for _ in range(rows)]
    for mono, val in terms:
        f = eval_monomial(mono, rho)
        if f:
            for i in range(rows):
                mi, vi = m[i], val[i]
                for j in range(cols):
                    if vi[j]:
                        mi[j] += f * vi[j]
    return m


_STATE_FORM = re.compile(r"^@(?:(x)([1-9]\d*)|(abs|sqrt|hinge|sqrtpos)\(x([1-9]\d*)\s*(?:([+-])\s*([0-9.]+(?:/[0-9+-]+)?))?\))$")
GRID_BITS = 32


def grid(v):
    """Nearest multiple of 2^-32, ties upward: floor(v*2^32 + 1/2) / 2^32."""
    s = v * 2 ** GRID_BITS + Fraction(1, 2)
    return Fraction(math.floor(s), 2 ** GRID_BITS)


def grid_sqrt(v):
    """floor(sqrt(|v|*4^b) + 1/2) / 2^b, exact."""
    n = abs(v) * 4 ** GRID_BITS
    a = math.isqrt(n.numerator // n.denominator)
    half = Fraction(2 * a + 1, 2)
    if n >= half * half:
        a += 1
    return Fraction(a, 2 ** GRID_BITS)


class StaticMap:
    def __init__(self, spec, what):
        check_keys(spec, ('kind', 'lower', 'upper', 'coefficients', 'range', 'knots', 'values'), what)
        self.kind = spec.get('kind')
        k = self.kind
        allowed = {'identity': (), 'abs': (), 'saturation': ('lower', 'upper'),
                   'dead_zone': ('lower', 'upper'), 'polynomial': ('coefficients',),
                   'piecewise_linear': ('knots', 'values')}
        if k not in allowed:
            raise Refused(f"{what}: unknown kind {k!r}")
        for key in ('lower', 'upper', 'coefficients', 'knots', 'values'):
            if (key in spec) != (key in allowed[k]):
                raise Refused(f"{what}: key '{key}' does not go with kind {k}")
        if k in ('saturation', 'dead_zone'):
            self.lo = parse_number(spec['lower'], what)
            self.hi = parse_number(spec['upper'], what)
            if self.lo > self.hi:
                raise Refused(f"{what}: lower > upper")
        if 'range' in spec and k != 'polynomial':
            raise Refused(f"{what}: key 'range' does not go with kind {k}")
        if k == 'polynomial':
            self.c = [parse_number(x, what) for x in spec['coefficients']]
            if not self.c:
                raise Refused(f"{what}: no coefficients")
            self.range = None
            if 'range' in spec:
                r = spec['range']
                if not isinstance(r, list) or len(r) != 2:
                    raise Refused(f"{what}: a range is [lo, hi]")
                self.range = (parse_number(r[0], what), parse_number(r[1], what))
                if self.range[0] > self.range[1]:
                    raise Refused(f"{what}: range lo > hi")
        if k == 'piecewise_linear':
            self.knots = [parse_number(x, what) for x in spec['knots']]
            self.vals = [parse_number(x, what) for x in spec['values']]
            if len(self.knots) < 2 or len(self.knots) != len(self.vals):
                raise Refused(f"{what}: knots and values")
            if any(b <= a for a, b in zip(self.knots, self.knots[1:])):
                raise Refused(f"{what}: knots must increase strictly")

    def identity(self):
        return self.kind == 'identity'

    def __call__(self, v):
        k = self.kind
        if k == 'identity':
            return v
        if k == 'abs':
            return abs(v)
        if k == 'saturation':
            return min(max(v, self.lo), self.hi)
        if k == 'dead_zone':
            if v > self.hi:
                return v - self.hi
            if v < self.lo:
                return v - self.lo
            return F0
        if k == 'polynomial':
            if self.range is not None and not (self.range[0] <= v <= self.range[1]):
                # beyond the fitted range: the tangent line at the nearer end,
                # p(e) + p'(e)(v - e), with p' from the coefficients k c_k
                e = self.range[0] if v < self.range[0] else self.range[1]
                value = sum(c * e ** i for i, c in enumerate(self.c))
                slope = sum(i * c * e ** (i - 1) for i, c in enumerate(self.c) if i > 0)
                return value + slope * (v - e)
            out = F0
            for c in reversed(self.c):
                out = out * v + c
            return out
        kn, va = self.knots, self.vals
        i = 0
        while i < len(kn) - 2 and v > kn[i + 1]:
            i += 1
        return va[i] + (va[i + 1] - va[i]) * (v - kn[i]) / (kn[i + 1] - kn[i])


class Model:
    """An lpvid-model/1 object, exact."""

    KEYS = ('format', 'description', 'states', 'inputs', 'outputs', 'scheduling', 'columns',
            'initial', 'correction', 'uncertainty', 'offset', 'state_offset', 'x0', 'static',
            'sample_time', 'units')

    def __init__(self, m):
        check_keys(m, self.KEYS, 'model')
        if m.get('format') != 'lpvid-model/1':
            raise Refused("model.format must be lpvid-model/1")
        for key in ('states', 'inputs', 'outputs', 'columns', 'initial'):
            if key not in m:
                raise Refused(f"model: '{key}' is required")
        self.nx = self._int(m['states'], 0, 'states')
        self.nu = self._int(m['inputs'], 1, 'inputs')
        self.ny = self._int(m['outputs'], 1, 'outputs')
        self.names = list(m.get('scheduling', []))
        for s in self.names:
            if not isinstance(s, str) or not _NAME.match(s):
                raise Refused(f"scheduling name {s!r}")
        if len(set(self.names)) != len(self.names):
            raise Refused("scheduling names must be distinct")
        cols = m['columns']
        check_keys(cols, ('u', 'y', 'rho'), 'model.columns')
        self.ucols = list(cols.get('u', []))
        self.ycols = list(cols.get('y', []))
        self.rhocols = list(cols.get('rho', self.names))
        if len(self.ucols) != self.nu or len(self.ycols) != self.ny or len(self.rhocols) != len(self.names):
            raise Refused("model.columns: wrong number of names")
        self.state_rho = {}
        for j, c in enumerate(self.rhocols):
            if isinstance(c, str) and c.startswith('@'):
                self.state_rho[j] = self._state_form(c)
        nx, nu, ny, names = self.nx, self.nu, self.ny, self.names
        ini = m['initial']
        check_keys(ini, ('A', 'B', 'C', 'D'), 'model.initial')
        self.A = parse_terms(ini.get('A'), names, nx, nx, 'A')
        self.B = parse_terms(ini.get('B'), names, nx, nu, 'B')
        self.C = parse_terms(ini.get('C'), names, ny, nx, 'C')
        self.D = parse_terms(ini.get('D'), names, ny, nu, 'D')
        corr = m.get('correction', {'basis': []})
        check_keys(corr, ('basis', 'A', 'B'), 'model.correction')
        self.corr_basis_text = list(corr.get('basis', []))
        self.corr_basis = [parse_monomial(b, names) for b in self.corr_basis_text]
        if len(set(self.corr_basis)) != len(self.corr_basis):
            raise Refused("correction basis functions must be distinct")
        cb = set(self.corr_basis)
        # The fixed A_i, B_i of the correction add to A(rho), B(rho) (eq. 8-10).
        self.A += parse_terms(corr.get('A'), names, nx, nx, 'correction A', cb)
        self.B += parse_terms(corr.get('B'), names, nx, nu, 'correction B', cb)
        unc = m.get('uncertainty', {'structure': 'multiplicative'})
        check_keys(unc, ('structure', 'weight', 'nz', 'C1', 'D1'), 'model.uncertainty')
        self.structure = unc.get('structure', 'multiplicative')
        if self.structure not in ('multiplicative', 'additive', 'general'):
            raise Refused("uncertainty.structure")
        if self.structure == 'general':
            if 'weight' in unc:
                raise Refused("uncertainty: no weight with the general structure")
            nz = unc.get('nz')
            if nz is None:
                for key in ('C1', 'D1'):
                    lst = unc.get(key) or []
                    if lst and isinstance(lst[0], dict) and isinstance(lst[0].get('value'), list) \
                            and len(lst[0]['value']) > 0:
                        nz = len(lst[0]['value'])
                        break
            if nz is None:
                raise Refused("uncertainty: nz cannot be determined")
            self.nz = self._int(nz, 1, 'nz')
            self.C1 = parse_terms(unc.get('C1'), names, self.nz, nx, 'C1')
            self.D1 = parse_terms(unc.get('D1'), names, self.nz, nu, 'D1')
            self.weight = None
        else:
            for key in ('nz', 'C1', 'D1'):
                if key in unc:
                    raise Refused(f"uncertainty: '{key}' only with the general structure")
            self.weight = parse_number(unc.get('weight', 1), 'uncertainty.weight')
            if self.weight <= 0:
                raise Refused("uncertainty.weight must be > 0")
            self.nz = ny if self.structure == 'multiplicative' else nu
        off = m.get('offset')
        self.off_basis = []
        self.off_values = None
        if off is not None:
            check_keys(off, ('basis', 'values'), 'model.offset')
            self.off_basis = [parse_monomial(b, names) for b in off.get('basis', [])]
            self.off_basis_text = list(off.get('basis', []))
            if 'values' in off:
                if not isinstance(off['values'], list) or len(off['values']) != len(self.off_basis):
                    raise Refused("offset: one value per basis function")
                self.off_values = [num_vector(v, ny, 'offset value') for v in off['values']]
        so = m.get('state_offset')
        self.so_basis, self.so_values = [], []
        if so is not None:
            check_keys(so, ('basis', 'values'), 'model.state_offset')
            self.so_basis = [parse_monomial(b, names) for b in so.get('basis', [])]
            if not isinstance(so.get('values'), list) or len(so['values']) != len(self.so_basis):
                raise Refused("state_offset: one value per basis function")
            self.so_values = [num_vector(v, nx, 'state_offset value') for v in so['values']]
        self.x0 = num_vector(m['x0'], nx, 'x0') if 'x0' in m else [F0] * nx
        st = m.get('static', {})
        check_keys(st, ('input_delay', 'input', 'output'), 'model.static')
        self.delay = self._int(st.get('input_delay', 0), 0, 'input_delay')
        self.gin = StaticMap(st.get('input', {'kind': 'identity'}), 'static.input')
        self.gout = StaticMap(st.get('output', {'kind': 'identity'}), 'static.output')

    @staticmethod
    def _int(v, lo, what):
        x = parse_number(v, what)
        if x.denominator != 1 or x < lo or x > 1000 and what != 'input_delay':
            raise Refused(f"model.{what} out of range")
        return int(x)

    def _state_form(self, text):
        m = _STATE_FORM.match(text)
        if not m:
            raise Unsupported(f"state column form '{text}'")
        if m.group(1):
            kind, idx, shift = 'x', int(m.group(2)), F0
        else:
            kind, idx = m.group(3), int(m.group(4))
            shift = F0
            if m.group(5):
                shift = parse_number(m.group(6), 'state column shift')
                if m.group(5) == '+':
                    shift = -shift
        if idx < 1 or idx > self.nx:
            raise Refused(f"state column '{text}' names no state")
        return kind, idx - 1, shift

    def state_rho_value(self, form, x):
        kind, idx, c = form
        v = x[idx] - c
        if kind == 'x':
            return grid(x[idx])
        if kind == 'abs':
            return grid(abs(v))
        if kind == 'hinge':
            return grid(max(v, F0))
        if kind == 'sqrt':
            return grid_sqrt(v)
        return grid_sqrt(max(v, F0))


# ----------------------------------------------------------------------------------------
# Data (docs/design.md section 4)
# ----------------------------------------------------------------------------------------

def read_data(path, sha256, names, rows, model, what):
    """The record's u, y, rho (exact) from the file's bytes; its hash must match."""
    try:
        with open(path, 'rb') as f:
            raw = f.read()
    except OSError as e:
        raise Refused(f"{what}: cannot read {path}: {e.strerror}")
    if hashlib.sha256(raw).hexdigest() != sha256:
        raise Refused(f"{what}: sha256 of {path} does not match the certificate")
    try:
        text = raw.decode('utf-8')
    except UnicodeDecodeError:
        raise Refused(f"{what}: not UTF-8 text")
    if text.startswith('\ufeff'):
        text = text[1:]
    lines = [ln for ln in text.splitlines() if ln.strip() != '']
    if names is not None:
        header = list(names)
        table = [ln.split() for ln in lines]
    else:
        if not lines:
            raise Refused(f"{what}: empty data file")
        parsed = [[c.strip() for c in row] for row in csv.reader(lines)]
        header, table = parsed[0], parsed[1:]
    for i, r in enumerate(table):
        if len(r) != len(header):
            raise Refused(f"{what}: row {i} has {len(r)} fields, header {len(header)}")
    if rows is not None:
        if (not isinstance(rows, list) or len(rows) != 2 or not all(isinstance(x, int) for x in rows)
                or not 0 <= rows[0] < rows[1] <= len(table)):
            raise Refused(f"{what}: rows window {rows} does not fit {len(table)} rows")
        table = table[rows[0]:rows[1]]
    if not table:
        raise Refused(f"{what}: no rows")

    def column(name):
        if header.count(name) != 1:
            raise Refused(f"{what}: column '{name}' not found once")
        j = header.index(name)
        return [parse_decimal_text(r[j], f"{what} column {name}") for r in table]

    u = transpose([column(c) for c in model.ucols])
    y = transpose([column(c) for c in model.ycols])
    rho_cols = []
    for j, c in enumerate(model.rhocols):
        rho_cols.append(None if j in model.state_rho else column(c))
    n = len(table)
    rho = [[(col[k] if col is not None else None) for col in rho_cols] for k in range(n)]
    return {'u': u, 'y': y, 'rho': rho, 'n': n}


# ----------------------------------------------------------------------------------------
# Simulation (docs/design.md sections 5.1-5.5)
# ----------------------------------------------------------------------------------------

def simulate(model, rec, x0, theta=None):
    """x, yhat (before the output map), z, the model output g_out(yhat + Phi) and r = y - it.
    theta (class claims): {'C': {i: ny x nx}, 'D': {i: ny x nu}, 'phi': {j: ny}} added to the
    model (correction C_i, D_i of eq. 10 on basis function i; offset values of eq. 20)."""
    nx, nu, ny, n = model.nx, model.nu, model.ny, rec['n']
    theta = theta or {}
    tC, tD, tphi = theta.get('C', {}), theta.get('D', {}), theta.get('phi', {})
    u_in = rec['u']
    d = model.delay
    up = [[model.gin(u_in[k - d if k >= d else 0][c]) for c in range(nu)] for k in range(n)]
    x = list(x0)
    xs, yhat, z, out, r, rhos = [], [], [], [], [], []
    for k in range(n):
        rho = list(rec['rho'][k])
        for j, form in model.state_rho.items():
            rho[j] = model.state_rho_value(form, x)
        A = eval_terms(model.A, rho, nx, nx)
        B = eval_terms(model.B, rho, nx, nu)
        C = eval_terms(model.C, rho, ny, nx)
        D = eval_terms(model.D, rho, ny, nu)
        for i, Ci in tC.items():
            f = eval_monomial(model.corr_basis[i], rho)
            C = [[a + f * b for a, b in zip(ra, rb)] for ra, rb in zip(C, Ci)]
        for i, Di in tD.items():
            f = eval_monomial(model.corr_basis[i], rho)
            D = [[a + f * b for a, b in zip(ra, rb)] for ra, rb in zip(D, Di)]
        uk = up[k]
        yk = [sum(C[i][c] * x[c] for c in range(nx)) + sum(D[i][c] * uk[c] for c in range(nu))
              for i in range(ny)]
        if model.structure == 'multiplicative':
            zk = [model.weight * v for v in yk]
        elif model.structure == 'additive':
            zk = [model.weight * v for v in uk]
        else:
            C1 = eval_terms(model.C1, rho, model.nz, nx)
            D1 = eval_terms(model.D1, rho, model.nz, nu)
            zk = [sum(C1[i][c] * x[c] for c in range(nx)) + sum(D1[i][c] * uk[c] for c in range(nu))
                  for i in range(model.nz)]
        phi = [F0] * ny
        if model.off_values is not None:
            for mono, val in zip(model.off_basis, model.off_values):
                f = eval_monomial(mono, rho)
                phi = [a + f * b for a, b in zip(phi, val)]
        for j, val in tphi.items():
            f = eval_monomial(model.off_basis[j], rho)
            phi = [a + f * b for a, b in zip(phi, val)]
        ok = [model.gout(a + b) for a, b in zip(yk, phi)]
        xs.append(x)
        rhos.append(rho)
        yhat.append(yk)
        z.append(zk)
        out.append(ok)
        r.append([a - b for a, b in zip(rec['y'][k], ok)])
        xn = [sum(A[i][c] * x[c] for c in range(nx)) + sum(B[i][c] * uk[c] for c in range(nu))
              for i in range(nx)]
        for mono, val in zip(model.so_basis, model.so_values):
            f = eval_monomial(mono, rho)
            xn = [a + f * b for a, b in zip(xn, val)]
        x = xn
    return {'x': xs, 'yhat': yhat, 'z': z, 'r': r, 'up': up, 'rho': rhos}


def leading_zero_samples(z):
    m = 0
    for zk in z:
        if any(v != 0 for v in zk):
            break
        m += 1
    return m


# ----------------------------------------------------------------------------------------
# Certificate: common part
# ----------------------------------------------------------------------------------------

TOP_KEYS = ('format', 'claim', 'data', 'records', 'model', 'toeplitz_mode', 'noise_normalisation',
            'delta2', 'dmax2', 'form', 'delta_taps', 'delta_horizon', 'w', 'objective', 'lambda',
            'lower_bound', 'dual', 'class', 'info')
CLAIMS = ('consistent', 'invalidated', 'lower_bound', 'not_a_witness', 'class_lower_bound',
          'class_invalidated')


def resolve_data_path(cert_dir, recorded, override):
    if override is not None:
        return override
    p = recorded if os.path.isabs(recorded) else os.path.join(cert_dir, recorded)
    if os.path.exists(p):
        return p
    return os.path.join(cert_dir, os.path.basename(recorded))


def load_records(cert, model, cert_dir, data_override):
    """[(rec, x0)] for 'data' (one record) or 'records' (several)."""
    if ('data' in cert) == ('records' in cert):
        raise Refused("exactly one of 'data' and 'records'")
    out = []
    if 'data' in cert:
        d = cert['data']
        check_keys(d, ('file', 'sha256', 'names', 'rows'), 'data')
        items = [(d, None)]
    else:
        if not isinstance(cert['records'], list) or len(cert['records']) < 2:
            raise Refused("records: two or more")
        if data_override is not None:
            raise Unsupported("--data with several records")
        items = []
        for k, d in enumerate(cert['records']):
            check_keys(d, ('file', 'sha256', 'names', 'rows', 'x0'), f'records[{k}]')
            items.append((d, d.get('x0')))
    for k, (d, x0) in enumerate(items):
        if not isinstance(d.get('file'), str) or not isinstance(d.get('sha256'), str):
            raise Refused("data: file and sha256 are required")
        if not re.match(r'^[0-9a-f]{64}$', d['sha256']):
            raise Refused("data.sha256 must be 64 lowercase hex digits")
        path = resolve_data_path(cert_dir, d['file'], data_override)
        rec = read_data(path, d['sha256'], d.get('names'), d.get('rows'), model, f'record {k}')
        x0v = num_vector(x0, model.nx, f'records[{k}].x0') if x0 is not None else list(model.x0)
        out.append((rec, x0v))
    return out


def get_nonneg(cert, key):
    if key not in cert:
        raise Refused(f"'{key}' is required")
    v = parse_number(cert[key], key)
    if v < 0:
        raise Refused(f"{key} is negative")
    return v


def forbid(cert, keys, why):
    for k in keys:
        if k in cert:
            raise Refused(f"'{k}' does not go with {why}")


# ----------------------------------------------------------------------------------------
# Theorem 2.1, primal: (C1) and (C2) of eq. 7
# ----------------------------------------------------------------------------------------

def primal_check(cert, model, sims, ns):
    """Returns (True, reason) when the primal point satisfies Theorem 2.1 at (delta2, dmax2),
    (False, reason) when it does not."""
    ny, nz = model.ny, model.nz
    delta2 = get_nonneg(cert, 'delta2')
    dmax2 = get_nonneg(cert, 'dmax2')
    forbid(cert, ('objective', 'lambda', 'lower_bound', 'dual', 'class'), 'a primal claim')
    form = cert.get('form')
    N = sum(ns) * ny
    if form == 'delta':
        forbid(cert, ('w',), "form 'delta'")
        if cert.get('toeplitz_mode') != 'signal':
            raise Refused("form delta needs toeplitz_mode signal")
        taps_raw = cert.get('delta_taps')
        L = cert.get('delta_horizon')
        if not isinstance(taps_raw, list) or not isinstance(L, int) or isinstance(L, bool) or L < 1:
            raise Refused("form delta needs delta_taps and an integer delta_horizon >= 1")
        K = len(taps_raw)
        if K > L:
            raise Refused("more taps than the horizon")
        if L > max(ns):
            raise Unsupported("a Delta horizon longer than the record")
        taps = [num_matrix([row], 1, ny * nz, f'delta_taps[{l}]')[0] for l in range(K) for row in [taps_raw[l]]]
        h = [[row[i * nz:(i + 1) * nz] for i in range(ny)] for row in taps]  # h[l][i][j]
        # z must vanish before the horizon in every record (causality, docs/design.md 7.3).
        for k, sim in enumerate(sims):
            for t in range(max(0, ns[k] - L)):
                if any(v != 0 for v in sim['z'][t]):
                    return False, f"z is non-zero at sample {t} of record {k}, before the Delta horizon"
        # (C2): d = r - Delta*z record by record from rest.
        dd = F0
        for k, sim in enumerate(sims):
            z, r = sim['z'], sim['r']
            for t in range(ns[k]):
                w = [F0] * ny
                for l in range(min(t + 1, K)):
                    zt = z[t - l]
                    hl = h[l]
                    for i in range(ny):
                        w[i] += sum(hl[i][j] * zt[j] for j in range(nz))
                dd += sum((a - b) ** 2 for a, b in zip(r[t], w))
        if dd > N * dmax2:
            return False, f"(C2) fails: ||d||^2 = {float(dd):.6g} > n*ny*dmax2 = {float(N * dmax2):.6g}"
        # (C1'): [delta2 I, T_Delta; T_Delta', I] >= 0  <=>  delta2 I - T T' >= 0.
        T = delta_toeplitz(h + [[[F0] * nz for _ in range(ny)]] * (L - K), L, ny, nz)
        if ny <= nz:
            G = matmul(T, transpose(T))
        else:
            G = matmul(transpose(T), T)
        S = [[(delta2 if i == j else F0) - G[i][j] for j in range(len(G))] for i in range(len(G))]
        ok, why = is_psd_rational(S)
        if not ok:
            return False, f"(C1) fails: delta2 I - T T' is not PSD ({why})"
        return True, f"(C2) holds (||d||^2 = {float(dd):.6g}); (C1) holds: ||T_Delta||^2 <= delta2 ({why})"
    if form == 'w':
        forbid(cert, ('delta_taps', 'delta_horizon'), "form 'w'")
        if len(sims) != 1:
            raise Refused("form w is one record only")
        n = ns[0]
        w = num_matrix(cert.get('w'), n, ny, 'w')
        sim = sims[0]
        dd = sum((a - b) ** 2 for rk, wk in zip(sim['r'], w) for a, b in zip(rk, wk))
        if dd > N * dmax2:
            return False, f"(C2) fails: ||d||^2 = {float(dd):.6g} > n*ny*dmax2"
        mode = cert.get('toeplitz_mode')
        if mode == 'signal':
            Tz = signal_toeplitz(sim['z'], n, nz)
        elif mode == 'paper':
            Tz = paper_tz(model, sim, n)
        else:
            raise Refused("toeplitz_mode")
        Tw = signal_toeplitz(w, n, ny)
        if delta2 == 0:
            if any(v != 0 for row in w for v in row):
                return False, "(C1) fails: delta2 = 0 but w is not zero"
            return True, "(C2) holds; (C1) holds with w = 0"
        # [Tz'Tz, Tw'; Tw, delta2 I] >= 0  <=>  delta2 Tz'Tz - Tw'Tw >= 0 (Schur, delta2 > 0).
        A = matmul(transpose(Tz), Tz)
        B = matmul(transpose(Tw), Tw)
        S = [[delta2 * a - b for a, b in zip(ra, rb)] for ra, rb in zip(A, B)]
        ok, why = is_psd_rational(S)
        if not ok:
            return False, f"(C1) fails: delta2 Tz'Tz - Tw'Tw is not PSD ({why})"
        return True, f"(C2) holds; (C1) holds ({why})"
    raise Refused(f"form {form!r} is not a primal form")


def delta_toeplitz(h, L, ny, nz):
    """T_Delta: L*ny x L*nz, block (a, b) = h_{a-b} for a >= b."""
    T = zeros(L * ny, L * nz)
    for a in range(L):
        for b in range(a + 1):
            hl = h[a - b]
            for i in range(ny):
                for j in range(nz):
                    T[a * ny + i][b * nz + j] = hl[i][j]
    return T


def signal_toeplitz(s, n, p):
    """T_s of eq. 3: (n*p) x n, block (k, j) = s_{k-j} (a p x 1 column) for k >= j."""
    T = zeros(n * p, n)
    for k in range(n):
        for j in range(k + 1):
            for i in range(p):
                T[k * p + i][j] = s[k - j][i]
    return T


def paper_tz(model, sim, n):
    """T_z = T_G12 T_u (eq. 2 and 4): G12 the map u -> z of the model from rest."""
    # With static input blocks G12 is driven by u' (docs/design.md 5.5: Theorem 2.1 applies with
    # u replaced by u'). Along a state-dependent rho, or with a state offset, the docs do not say
    # what T_G12 is.
    if model.state_rho or model.so_basis:
        raise Unsupported("toeplitz mode paper with state scheduling or a state offset")
    nx, nu, nz = model.nx, model.nu, model.nz
    u = sim['up']
    rhos = sim['rho']
    mats = []
    for k in range(n):
        rho = rhos[k]
        A = eval_terms(model.A, rho, nx, nx)
        B = eval_terms(model.B, rho, nx, nu)
        if model.structure == 'general':
            C1 = eval_terms(model.C1, rho, nz, nx)
            D1 = eval_terms(model.D1, rho, nz, nu)
        elif model.structure == 'multiplicative':
            C1 = [[model.weight * v for v in row] for row in eval_terms(model.C, rho, model.ny, nx)]
            D1 = [[model.weight * v for v in row] for row in eval_terms(model.D, rho, model.ny, nu)]
        else:
            C1 = zeros(nz, nx)
            D1 = [[model.weight if i == j else F0 for j in range(nu)] for i in range(nz)]
        mats.append((A, B, C1, D1))
    # Column c of T_G12 T_u is G12 (from rest, along the recorded rho) driven by u delayed by c.
    Tz = zeros(n * nz, n)
    for c in range(n):
        x = [F0] * nx
        for k in range(c, n):
            A, B, C1, D1 = mats[k]
            v = u[k - c]
            for i in range(nz):
                Tz[k * nz + i][c] = sum(C1[i][q] * x[q] for q in range(nx)) + sum(D1[i][q] * v[q] for q in range(nu))
            x = [sum(A[i][q] * x[q] for q in range(nx)) + sum(B[i][q] * v[q] for q in range(nu)) for i in range(nx)]
    return Tz


# ----------------------------------------------------------------------------------------
# Dual points of the full-horizon Delta form (docs/dual_certificates.md)
# ----------------------------------------------------------------------------------------

def adjoint_C(g_recs, z_recs, L, ny, nz):
    """C_l(g) = sum over records and samples j >= l of g_j z_{j-l}' (ny x nz), l < L."""
    out = []
    for l in range(L):
        c = [[F0] * nz for _ in range(ny)]
        for g, z in zip(g_recs, z_recs):
            for j in range(l, len(g)):
                zj = z[j - l]
                if not any(zj):
                    continue
                gj = g[j]
                for i in range(ny):
                    if gj[i]:
                        ci = c[i]
                        for q in range(nz):
                            ci[q] += gj[i] * zj[q]
        out.append(c)
    return out


def parse_dual_common(dual, ny, ns, what):
    sigma = parse_number(dual.get('sigma'), f'{what}.sigma')
    if sigma <= 0:
        raise Refused(f"{what}: sigma must be > 0")
    N = sum(ns)
    g = num_matrix(dual.get('g'), N, ny, f'{what}.g')
    g_recs, at = [], 0
    for n in ns:
        g_recs.append(g[at:at + n])
        at += n
    return sigma, g_recs


def dense_dual_terms(dual, L, ny, nz, Cl, what):
    """Dense Y1: the dual equality Omega_l(W) = C_l(g) exactly, Y1 >= 0 exactly.
    Returns (trU, trV)."""
    P = L * (ny + nz)
    rows = dual.get('Y1')
    if not isinstance(rows, list) or len(rows) != P:
        raise Refused(f"{what}: Y1 must have {P} rows")
    Y = zeros(P, P)
    for i, row in enumerate(rows):
        if not isinstance(row, list) or len(row) != P - i:
            raise Refused(f"{what}: Y1 row {i} must have {P - i} entries")
        for j, v in enumerate(row):
            x = parse_number(v, f'{what}.Y1')
            Y[i][i + j] = x
            Y[i + j][i] = x
    Lu = L * ny
    for l in range(L):
        for i in range(ny):
            for q in range(nz):
                s = sum(Y[(b + l) * ny + i][Lu + b * nz + q] for b in range(L - l))
                if s != Cl[l][i][q]:
                    return None, f"the dual equality fails at lag {l}, entry ({i},{q})"
    ok, why = is_psd_rational(Y)
    if not ok:
        return None, f"Y1 is not PSD ({why})"
    trU = sum(Y[i][i] for i in range(Lu))
    trV = sum(Y[i][i] for i in range(Lu, P))
    return (trU, trV), why


def decimal_inverse_spd(M, prec=60):
    """Inverse of a symmetric positive definite Decimal matrix by Cholesky, or None."""
    getcontext().prec = prec
    n = len(M)
    Lc = [[Decimal(0)] * n for _ in range(n)]
    for j in range(n):
        s = M[j][j] - sum(Lc[j][k] * Lc[j][k] for k in range(j))
        if s <= 0:
            return None
        Lc[j][j] = s.sqrt()
        for i in range(j + 1, n):
            Lc[i][j] = (M[i][j] - sum(Lc[i][k] * Lc[j][k] for k in range(j))) / Lc[j][j]
    # inverse of the lower factor, then inv(M) = inv(L)' inv(L)
    Li = [[Decimal(0)] * n for _ in range(n)]
    for i in range(n):
        Li[i][i] = 1 / Lc[i][i]
        for j in range(i):
            Li[i][j] = -sum(Lc[i][k] * Li[k][j] for k in range(j, i)) / Lc[i][i]
    inv = [[Decimal(0)] * n for _ in range(n)]
    for i in range(n):
        for j in range(i, n):
            v = sum(Li[k][i] * Li[k][j] for k in range(j, n))
            inv[i][j] = v
            inv[j][i] = v
    return inv


def to_decimal(fr):
    return Decimal(fr.numerator) / Decimal(fr.denominator)


def path_dual_terms(dual, L, ny, nz, Cl, what):
    """Compact form: rebuild U from (taps, t, mu, e), E from the residual of the dual equality,
    and decide Y1 = J [U, E; E', xI] J' >= 0 by U - gamma I >= 0 and ||E||_F^2 <= x gamma.
    Returns (trU, trV)."""
    taps_raw = dual.get('taps')
    if not isinstance(taps_raw, list) or len(taps_raw) != L:
        raise Refused(f"{what}: taps must have {L} rows")
    taps = [num_vector(row, ny * nz, f'{what}.taps') for row in taps_raw]
    h = [[row[i * nz:(i + 1) * nz] for i in range(ny)] for row in taps]
    t = parse_number(dual.get('t'), f'{what}.t')
    mu = parse_number(dual.get('mu'), f'{what}.mu')
    x = parse_number(dual.get('x'), f'{what}.x')
    gamma = parse_number(dual.get('u_floor'), f'{what}.u_floor')
    e = dual.get('u_exponent')
    if not isinstance(e, int) or isinstance(e, bool) or abs(e) > 4000:
        raise Refused(f"{what}: u_exponent must be an integer in [-4000, 4000]")
    if t <= 0 or mu <= 0 or x <= 0 or gamma < 0:
        raise Refused(f"{what}: needs t > 0, mu > 0, x > 0, u_floor >= 0")
    T = delta_toeplitz(h, L, ny, nz)
    Lu = L * ny
    # U_d = mu (t I - T T')^-1, in high-precision decimal (its value is trusted for nothing).
    TT = matmul(T, transpose(T))
    Md = [[to_decimal((t if i == j else F0) - TT[i][j]) for j in range(Lu)] for i in range(Lu)]
    inv = decimal_inverse_spd(Md)
    if inv is None:
        return None, "t I - T T' is not positive definite: no U"
    mud = to_decimal(mu)
    scale = Decimal(2) ** (-e)
    Ut = [[0] * Lu for _ in range(Lu)]
    for i in range(Lu):
        for j in range(i, Lu):
            v = int((mud * inv[i][j] * scale).to_integral_value(rounding=ROUND_HALF_EVEN))
            Ut[i][j] = v
            Ut[j][i] = v
    two_e = Fraction(2) ** e
    # UT exactly (U = Ut 2^e).
    UT = [[two_e * sum(Ut[i][k] * T[k][c] for k in range(Lu) if T[k][c]) for c in range(L * nz)]
          for i in range(Lu)]
    R = []
    for l in range(L):
        Rl = [[Cl[l][i][q] + sum(UT[(b + l) * ny + i][b * nz + q] for b in range(L - l)) for q in range(nz)]
              for i in range(ny)]
        R.append(Rl)
    E2 = sum(sum(v * v for row in R[l] for v in row) / (L - l) for l in range(L))
    if E2 > x * gamma:
        return None, f"||E||_F^2 = {float(E2):.6g} exceeds x*u_floor = {float(x * gamma):.6g}"
    # U - gamma I >= 0 on integers: Ut * 2^e - gamma I, scaled.
    gq = gamma / two_e
    d = gq.denominator
    Mi = [[Ut[i][j] * d - (gq.numerator if i == j else 0) for j in range(Lu)] for i in range(Lu)]
    ok, why = is_psd_integer(Mi)
    if not ok:
        return None, f"U - u_floor I is not PSD ({why})"
    trU = two_e * sum(Ut[i][i] for i in range(Lu))
    trTUT = sum(T[i][c] * UT[i][c] for i in range(Lu) for c in range(L * nz) if T[i][c])
    hR = sum(h[l][i][q] * R[l][i][q] for l in range(L) for i in range(ny) for q in range(nz))
    trV = trTUT - 2 * hR + x * L * nz
    return (trU, trV), f"U - u_floor I {why}"


def dual_terms(dual, form, L, ny, nz, Cl, what):
    if form == 'dual_delta':
        for k in ('taps', 't', 'mu', 'u_exponent', 'x', 'u_floor'):
            if k in dual:
                raise Refused(f"{what}: '{k}' does not go with form dual_delta")
        return dense_dual_terms(dual, L, ny, nz, Cl, what)
    if form == 'dual_delta_path':
        if 'Y1' in dual:
            raise Refused(f"{what}: Y1 does not go with form dual_delta_path")
        return path_dual_terms(dual, L, ny, nz, Cl, what)
    raise Refused(f"form {form!r} is not a dual form")


def objective_of(cert):
    """(objective, fixed values) of a dual claim, with the schema's key rules."""
    obj = cert.get('objective')
    claim = cert['claim']
    if claim in ('invalidated', 'class_invalidated'):
        if obj != 'feasibility':
            raise Refused("an invalidation has objective feasibility")
        forbid(cert, ('lambda', 'lower_bound'), 'an invalidation')
        return obj, get_nonneg(cert, 'delta2'), get_nonneg(cert, 'dmax2'), None, None
    if obj not in ('min_delta', 'min_dmax', 'weighted'):
        raise Refused("a lower bound has objective min_delta, min_dmax or weighted")
    if 'lower_bound' not in cert:
        raise Refused("'lower_bound' is required")
    lb = parse_number(cert['lower_bound'], 'lower_bound')  # a negative claim is trivially true
    if obj == 'min_delta':
        forbid(cert, ('delta2', 'lambda'), 'objective min_delta')
        return obj, None, get_nonneg(cert, 'dmax2'), None, lb
    if obj == 'min_dmax':
        forbid(cert, ('dmax2', 'lambda'), 'objective min_dmax')
        return obj, get_nonneg(cert, 'delta2'), None, None, lb
    forbid(cert, ('delta2', 'dmax2'), 'objective weighted')
    lam = get_nonneg(cert, 'lambda')
    if lam > 1:
        raise Refused("lambda must be in [0, 1]")
    return obj, None, None, lam, lb


# Every bound the last checks computed (one per dual point or leaf; the margin for a fixed
# (delta, dmax)), exact: the test builds claims just above and just below them.
BOUNDS = []


def bound_holds(obj, delta2, dmax2, lam, lb, trU, beta, Nsig):
    """From  t*trU + s*Nsig >= beta  at every feasible (t = delta^2, s = dmax^2 >= 0):
    decide the claim. Returns (holds, text)."""
    if obj == 'feasibility':
        gap = beta - delta2 * trU - dmax2 * Nsig
        return gap > 0, f"beta - delta2 trU - N dmax2 sigma = {float(gap):.6g}"
    if obj == 'min_delta':
        if trU <= 0:
            return lb == 0, "trU = 0: only the bound 0"
        b = (beta - dmax2 * Nsig) / trU
    elif obj == 'min_dmax':
        b = (beta - delta2 * trU) / Nsig
    else:
        if beta <= 0 or trU <= 0:
            b = F0
        else:
            b = beta * min(lam / trU, (1 - lam) / Nsig)
    b = max(b, F0)
    BOUNDS.append(b)
    return lb <= b, f"bound {float(b):.10g} vs claimed {float(lb):.10g}"


def closed_form_check(cert, model, sims, ns):
    """Forms 'zero_delta' and 'nonnegative' (docs/dual_certificates.md, "The delta = 0 lower end"):
    no dual point. At delta^2 = 0 the block delta^2 I of (C1) is zero, so T_w = 0 (a PSD matrix
    with a zero diagonal entry has a zero row there), w = 0 and d = r: n*ny*dmax^2 >= ||r||^2 at
    every feasible point, with equality at Delta = 0. Every objective is >= 0."""
    form = cert.get('form')
    forbid(cert, ('delta_taps', 'delta_horizon', 'w', 'class', 'dual'), f"form {form}")
    mode = cert.get('toeplitz_mode')
    if mode == 'paper':
        if len(sims) != 1:
            raise Refused("toeplitz mode paper is one record only")
        if model.state_rho or model.so_basis:
            raise Unsupported("toeplitz mode paper with state scheduling or a state offset")
    obj, delta2, dmax2, lam, lb = objective_of(cert)
    if form == 'nonnegative':
        if cert['claim'] != 'lower_bound':
            return False, "form nonnegative proves no invalidation"
        return lb <= 0, f"claimed lower end {float(lb):.10g} against 0 (every objective is >= 0)"
    if obj not in ('min_dmax', 'feasibility'):
        return False, f"form zero_delta decides dmax^2 at delta^2 = 0 only, not objective {obj}"
    if delta2 != 0:
        return False, f"form zero_delta needs delta2 = 0, not {float(delta2):.6g}"
    rr = sum(v * v for sim in sims for row in sim['r'] for v in row)
    N = sum(ns) * model.ny
    if obj == 'feasibility':
        return N * dmax2 < rr, f"n*ny*dmax2 = {float(N * dmax2):.10g} against ||r||^2 = {float(rr):.10g}"
    BOUNDS.append(rr / N)
    return N * lb <= rr, f"n*ny*lower_bound = {float(N * lb):.10g} against ||r||^2 = {float(rr):.10g}"


def fixed_dual_check(cert, model, sims, ns):
    if cert.get('form') in ('zero_delta', 'nonnegative'):
        return closed_form_check(cert, model, sims, ns)
    ny, nz = model.ny, model.nz
    forbid(cert, ('delta_taps', 'delta_horizon', 'w', 'class'), 'a dual claim')
    if cert.get('toeplitz_mode') != 'signal':
        raise Refused("dual claims need toeplitz_mode signal")
    obj, delta2, dmax2, lam, lb = objective_of(cert)
    dual = cert.get('dual')
    check_keys(dual, ('horizon', 'sigma', 'g', 'Y1', 'taps', 't', 'mu', 'u_exponent', 'x', 'u_floor'),
               'dual')
    L = max(n - leading_zero_samples(s['z']) for n, s in zip(ns, sims))
    if L == 0:
        raise Refused("z is zero on every sample: no horizon")
    if dual.get('horizon') != L:
        return False, f"dual.horizon {dual.get('horizon')} differs from n - (leading zeros of z) = {L}"
    sigma, g_recs = parse_dual_common(dual, ny, ns, 'dual')
    Cl = adjoint_C(g_recs, [s['z'] for s in sims], L, ny, nz)
    terms, why = dual_terms(dual, cert.get('form'), L, ny, nz, Cl, 'dual')
    if terms is None:
        return False, why
    trU, trV = terms
    gg = sum(v * v for g in g_recs for row in g for v in row)
    gr = sum(a * b for g, s in zip(g_recs, sims) for gr_, rr in zip(g, s['r']) for a, b in zip(gr_, rr))
    beta = -(trV + gg / sigma + 2 * gr)
    N = sum(ns) * ny
    ok, text = bound_holds(obj, delta2, dmax2, lam, lb, trU, beta, N * sigma)
    return ok, f"{text}; {why}"


# ----------------------------------------------------------------------------------------
# Class claims (docs/class_lower_bound.md)
# ----------------------------------------------------------------------------------------

_PARAM = re.compile(r'^(C|D)\[(.+)\]\((\d+),(\d+)\)$')
_X0 = re.compile(r'^x0(?:\[(\d+)\])?\((\d+)\)$')
_PHI = re.compile(r'^(?:phi|offset|Phi)\[(.+)\]\((\d+)\)$')


def class_parameters(model, unknowns, nrec):
    """This checker's own list of the unknowns p: name -> (kind, ...)."""
    params = {}
    if unknowns['correction']:
        for i, text in enumerate(model.corr_basis_text):
            for r in range(model.ny):
                for c in range(model.nx):
                    params[('C', i, r, c)] = None
                for c in range(model.nu):
                    params[('D', i, r, c)] = None
    if unknowns['offset']:
        if model.off_values is not None:
            raise Refused("class: offset unknown but the model's offset has values")
        for j in range(len(model.off_basis)):
            for r in range(model.ny):
                params[('phi', j, r)] = None
    if unknowns['x0']:
        for k in range(nrec):
            for c in range(model.nx):
                params[('x0', k, c)] = None
    return params


def parse_param_name(name, model, nrec):
    m = _PARAM.match(name)
    if m:
        mono = parse_monomial(m.group(2), model.names)
        if mono not in model.corr_basis:
            raise Refused(f"parameter {name}: not a correction basis function")
        return (m.group(1), model.corr_basis.index(mono), int(m.group(3)) - 1, int(m.group(4)) - 1)
    m = _X0.match(name)
    if m:
        k = int(m.group(1)) - 1 if m.group(1) else 0
        if m.group(1) is None and nrec > 1:
            raise Refused(f"parameter {name}: several records name x0[k](c)")
        return ('x0', k, int(m.group(2)) - 1)
    m = _PHI.match(name)
    if m:
        mono = parse_monomial(m.group(1), model.names)
        if mono not in model.off_basis:
            raise Refused(f"parameter {name}: not an offset basis function")
        return ('phi', model.off_basis.index(mono), int(m.group(2)) - 1)
    raise Unsupported(f"parameter name '{name}'")


def sim_at(model, recs, keys, p):
    """Simulate every record at the parameter vector p (a dict index -> value, zeros omitted):
    the correction and offset enter the model, the x0 entries move the record's initial state."""
    theta = {'C': {}, 'D': {}, 'phi': {}}
    dx0 = {}
    for idx, v in p.items():
        key = keys[idx]
        if key[0] in ('C', 'D'):
            _, i, r, c = key
            cols = model.nx if key[0] == 'C' else model.nu
            mat = theta[key[0]].setdefault(i, zeros(model.ny, cols))
            mat[r][c] += v
        elif key[0] == 'phi':
            _, j, r = key
            vec = theta['phi'].setdefault(j, [F0] * model.ny)
            vec[r] += v
        else:
            _, k, c = key
            dx0.setdefault(k, [F0] * model.nx)[c] += v
    out = []
    for k, (rec, x0) in enumerate(recs):
        x = list(x0)
        if k in dx0:
            x = [a + b for a, b in zip(x, dx0[k])]
        out.append(simulate(model, rec, x, theta))
    return out


def stack(sims, key):
    return [v for s in sims for row in s[key] for v in row]


def affine_build(model, recs, keys, names):
    """z0, r0 and the columns Jz_i, Jr_i by simulation, with affinity checked exactly.
    The signals are polynomials of degree <= 2 in p when the state does not depend on p
    nonlinearly and the output map is the identity (enforced before), so zero second
    differences at 0, e_i, e_j, e_i + e_j, 2 e_i prove them affine."""
    P = len(keys)
    base = sim_at(model, recs, keys, {})
    z0, r0 = stack(base, 'z'), stack(base, 'r')
    unit = [sim_at(model, recs, keys, {i: F1}) for i in range(P)]
    Jz = [[a - b for a, b in zip(stack(u, 'z'), z0)] for u in unit]
    Jr = [[b - a for a, b in zip(stack(u, 'r'), r0)] for u in unit]  # r(p) = r0 - Jr p
    zu = [stack(u, 'z') for u in unit]
    ru = [stack(u, 'r') for u in unit]
    for i in range(P):
        for j in range(i, P):
            p = {i: F1 + (1 if i == j else 0)} if i == j else {i: F1, j: F1}
            s = sim_at(model, recs, keys, p)
            for sig, base_v, ui in (('z', z0, zu), ('r', r0, ru)):
                both = stack(s, sig)
                if any(a - b - c + d != 0 for a, b, c, d in zip(both, ui[i], ui[j], base_v)):
                    raise Refused(f"the residual is not affine in the unknowns: parameters "
                                  f"{names[i]} and {names[j]} interact (in {sig})")
    return base, Jz, Jr


def check_class_model(model, unknowns):
    if not model.gout.identity():
        raise Unsupported("class claims with a static output map (the residual is not polynomial in p)")
    if unknowns['x0'] and model.state_rho:
        raise Refused("x0 is an unknown and the scheduling depends on the state: the residual is not "
                      "polynomial in x0, so no finite set of differences proves it affine")


def class_check(cert, model, recs, ns):
    ny, nz = model.ny, model.nz
    forbid(cert, ('delta_taps', 'delta_horizon', 'w', 'dual'), 'a class claim')
    if cert.get('toeplitz_mode') != 'signal':
        raise Refused("class claims need toeplitz_mode signal")
    form = cert.get('form')
    obj, delta2, dmax2, lam, lb = objective_of(cert)
    cls = cert.get('class')
    check_keys(cls, ('unknowns', 'parameters', 'free', 'center', 'radius', 'horizon', 'nodes'), 'class')
    unk = cls.get('unknowns')
    check_keys(unk, ('correction', 'offset', 'x0'), 'class.unknowns')
    if set(unk) != {'correction', 'offset', 'x0'} or not all(isinstance(v, bool) for v in unk.values()):
        raise Refused("class.unknowns needs three booleans")
    check_class_model(model, unk)
    names = cls.get('parameters')
    if not isinstance(names, list) or not all(isinstance(s, str) for s in names):
        raise Refused("class.parameters")
    keys = [parse_param_name(s, model, len(recs)) for s in names]
    own = class_parameters(model, unk, len(recs))
    if sorted(map(str, keys)) != sorted(map(str, own)) or len(set(keys)) != len(keys):
        raise Refused("class.parameters do not name exactly the unknowns of the model")
    P = len(keys)
    free = cls.get('free')
    if not isinstance(free, list) or not all(isinstance(i, int) and 0 <= i < P for i in free) \
            or len(set(free)) != len(free):
        raise Refused("class.free")
    free = set(free)
    center = num_vector(cls.get('center'), P, 'class.center')
    radius = num_vector(cls.get('radius'), P, 'class.radius')
    if any(r < 0 for r in radius):
        raise Refused("class.radius must be >= 0")
    base, Jz, Jr = affine_build(model, recs, keys, names)
    for i in free:
        if any(Jz[i]):
            return False, f"free parameter {names[i]} moves z"
    # class horizon: leading samples where z0 and every Jz column vanish, per record
    Lh = 0
    at = 0
    for k, n in enumerate(ns):
        m = 0
        for t in range(n):
            sl = slice((at + t) * nz, (at + t + 1) * nz)
            if any(base[k]['z'][t]) or any(any(col[sl]) for col in Jz):
                break
            m += 1
        Lh = max(Lh, n - m)
        at += n
    if Lh == 0:
        raise Refused("z is zero for every p: no horizon")
    if cls.get('horizon') != Lh:
        return False, f"class.horizon {cls.get('horizon')} differs from {Lh}"
    nodes = cls.get('nodes')
    if not isinstance(nodes, list) or not nodes:
        raise Refused("class.nodes")
    free_cols = [Jr[i] for i in sorted(free)]
    bounded = [i for i in range(P) if i not in free]
    s_z = {i: sqrt_upper(sum(v * v for v in Jz[i])) for i in bounded}
    N = sum(ns) * ny
    state = {'pos': 0, 'leaves': 0, 'worst': None}

    def leaf_check(leaf, c, rad):
        check_keys(leaf, ('horizon', 'sigma', 'g', 'Y1', 'taps', 't', 'mu', 'u_exponent', 'x', 'u_floor',
                          'epsilon', 'expansion'), 'leaf')
        if leaf.get('horizon') != Lh:
            return False, f"leaf horizon {leaf.get('horizon')} differs from {Lh}"
        eps = parse_number(leaf.get('epsilon'), 'leaf.epsilon')
        if eps <= 0:
            raise Refused("leaf epsilon must be > 0")
        pe = num_vector(leaf['expansion'], P, 'leaf.expansion') if 'expansion' in leaf else list(c)
        sigma, g_recs = parse_dual_common(leaf, ny, ns, 'leaf')
        gt = [v for g in g_recs for row in g for v in row]
        g = column_space_projector_apply(free_cols, gt)
        # the signals at the expansion point, simulated (affinity was proven above)
        pdict = {i: pe[i] for i in range(P) if i not in free and pe[i] != 0}
        sims_e = sim_at(model, recs, keys, pdict)
        g_recs2, at2 = [], 0
        for n in ns:
            g_recs2.append([g[(at2 + t) * ny:(at2 + t + 1) * ny] for t in range(n)])
            at2 += n
        Cl = adjoint_C(g_recs2, [s['z'] for s in sims_e], Lh, ny, nz)
        terms, why = dual_terms(leaf, form, Lh, ny, nz, Cl, 'leaf')
        if terms is None:
            return False, why
        trU, trV = terms
        re_ = stack(sims_e, 'r')
        beta = -(trV + sum(v * v for v in g) / sigma + 2 * sum(a * b for a, b in zip(g, re_)))
        rp = {i: abs(pe[i] - c[i]) + rad[i] for i in bounded}
        lin = 2 * sum(rp[i] * abs(sum(a * b for a, b in zip(Jr[i], g))) for i in bounded)
        sg = sqrt_upper(sum(v * v for v in g))
        cc = 2 * sg * sum(rp[i] * s_z[i] for i in bounded)
        trU2 = trU + cc / (2 * eps)
        beta2 = beta - lin - cc * eps / 2
        return bound_holds(obj, delta2, dmax2, lam, lb, trU2, beta2, N * sigma)

    def walk(c, rad):
        if state['pos'] >= len(nodes):
            raise Refused("class.nodes: the tree ends early")
        node = nodes[state['pos']]
        state['pos'] += 1
        if not isinstance(node, dict) or len(node) != 1:
            raise Refused("class node must be {'split': i} or {'leaf': ...}")
        if 'split' in node:
            i = node['split']
            if not isinstance(i, int) or isinstance(i, bool) or not 0 <= i < P or i in free:
                raise Refused(f"split on {i!r}: not a bounded parameter")
            half = rad[i] / 2
            lo_c, hi_c = list(c), list(c)
            lo_c[i] -= half
            hi_c[i] += half
            r2 = list(rad)
            r2[i] = half
            ok, why = walk(lo_c, r2)
            if not ok:
                return ok, why
            return walk(hi_c, r2)
        if 'leaf' in node:
            state['leaves'] += 1
            ok, why = leaf_check(node['leaf'], c, rad)
            if not ok:
                return False, f"leaf {state['leaves']}: {why}"
            return True, why
        raise Refused("class node must be split or leaf")

    ok, why = walk(center, radius)
    if ok and state['pos'] != len(nodes):
        raise Refused("class.nodes: nodes after the end of the tree")
    if not ok:
        return False, why
    return True, f"{state['leaves']} leaves over {P} parameters ({len(free)} free); last: {why}"


# ----------------------------------------------------------------------------------------
# Top level
# ----------------------------------------------------------------------------------------

def check_certificate(path, data_override=None):
    """Returns ('holds' | 'refused' | 'unsupported', reason)."""
    try:
        with open(path, 'rb') as f:
            text = f.read().decode('utf-8')
        cert = load_json_exact(text)
        return _check(cert, os.path.dirname(os.path.abspath(path)), data_override)
    except Refused as e:
        return 'refused', str(e)
    except Unsupported as e:
        return 'unsupported', str(e)
    except (ValueError, UnicodeDecodeError, json.JSONDecodeError, OSError) as e:
        return 'refused', f"unreadable: {e}"


def _check(cert, cert_dir, data_override):
    check_keys(cert, TOP_KEYS, 'certificate')
    if cert.get('format') != 'lpvid-certificate/1':
        raise Refused("format must be lpvid-certificate/1")
    claim = cert.get('claim')
    if claim not in CLAIMS:
        raise Refused(f"unknown claim {claim!r}")
    if cert.get('noise_normalisation') != 'rms':
        raise Refused("noise_normalisation must be rms")
    if cert.get('toeplitz_mode') not in ('signal', 'paper'):
        raise Refused("toeplitz_mode")
    model = Model(cert.get('model'))
    recs = load_records(cert, model, cert_dir, data_override)
    ns = [rec['n'] for rec, _ in recs]
    if model.off_basis and model.off_values is None and claim not in ('class_lower_bound', 'class_invalidated'):
        raise Refused("the model's offset has no values: a fixed-model claim leaves no unknowns")
    if claim in ('class_lower_bound', 'class_invalidated'):
        ok, why = class_check(cert, model, recs, ns)
        verdict = claim
    else:
        sims = [simulate(model, rec, x0) for rec, x0 in recs]
        if claim in ('consistent', 'not_a_witness'):
            ok, why = primal_check(cert, model, sims, ns)
            if claim == 'not_a_witness':
                ok = not ok
        else:
            ok, why = fixed_dual_check(cert, model, sims, ns)
        verdict = claim
    if ok:
        return 'holds', f"{verdict}: {why}"
    return 'refused', f"{verdict} does not hold: {why}"


def main(argv):
    args = argv[1:]
    data = None
    if '--data' in args:
        i = args.index('--data')
        if i + 1 >= len(args):
            print("usage: exact_checker.py CERT [--data FILE]", file=sys.stderr)
            return 2
        data = args[i + 1]
        del args[i:i + 2]
    if len(args) != 1:
        print("usage: exact_checker.py CERT [--data FILE]", file=sys.stderr)
        return 2
    verdict, reason = check_certificate(args[0], data)
    print(f"{verdict}: {reason}")
    return {'holds': 0, 'refused': 1, 'unsupported': 3}[verdict]


if __name__ == '__main__':
    sys.exit(main(sys.argv))
