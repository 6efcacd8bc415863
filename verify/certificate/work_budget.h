#pragma once
/// The whole check of one certificate against --max-total-work
/// and --max-floating-work (verify/psd/work_limits.h): its parts estimated from the sizes the
/// certificate and its data declare, in the operations of max_exact_work
/// (one modular multiply-add, or about one 64-bit limb operation of an exact
/// product, or one floating multiply-add), each charged before its work
/// starts. Beyond the limit: WorkLimitError naming the part and the
/// estimate, nothing decided.
///
///  - the dual points: one per class leaf (one for a dual claim), each a
///    floating rebuild of order m = L·ny (or L·(ny+nz) for a dense Y1),
///    about m³ multiply-adds against --max-floating-work, and its exact
///    sums, L²·(ny·nz)² operations;
///  - a primal point's (C1) check, of order L·min(ny, nz) (form "delta") or
///    n (form "w"): m³; for one output and one input on a horizon of 4096 or
///    more, the proof in doubles (verify/certificate/tap_gram_filter.h):
///    L³/6 + L² multiply-adds against --max-floating-work, and the exact
///    matrix's m³ only if that proof fails;
///  - the records: more than --max-records is refused, each costs a fixed
///    amount; every data file's bytes are read, hashed and parsed once;
///  - the exact simulation: the state's numbers grow by about g bits per
///    sample (g: the bits of the model's state matrices and of the
///    scheduling, numerator plus denominator), so sample k of a record holds
///    numbers of about b₀ + g·k bits; the simulation costs its step's
///    products times Σₖ (b₀ + g·k)/64 limbs, quadratic in the record's
///    length, once plus once per class parameter (the affine signals), and
///    every convolution of the simulated z with L taps (the Δ taps, the dual
///    point's adjoint at each leaf, a Gram of z) L·ny·nz times that sum.
/// The constants are calibrated in docs/exit_codes.md.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "data/experiment.h"
#include "verify/certificate/certificate.h"

namespace lpvid {

/// Starts the total and charges what the certificate alone declares: its
/// dual points (class leaves) and its records (refused beyond --max-records).
void charge_declared_work(const Certificate& c);

/// Before the certificate's text is parsed into numbers (about 70 bytes of
/// memory per byte of text): a streaming pass that keeps only the nesting
/// counts the dual points the text declares (class leaves, a dual point) and
/// their horizons and the model's outputs, and refuses (WorkLimitError) when
/// their rebuild alone, as charge_declared_work estimates it, is beyond
/// --max-floating-work. Text that this pass cannot read is left to the parser
/// (an early refusal only: charge_declared_work charges the parsed sizes).
void refuse_declared_text(std::string_view text, const std::string& file);

/// Charges reading, hashing and parsing one data file of `bytes` bytes.
void charge_data_file(std::uintmax_t bytes, const std::string& path);

/// Most bits (numerator plus denominator) of the data's numbers: inputs and
/// outputs, and the scheduling (which multiplies the state at every step).
struct DataBits {
  double signals = 0, scheduling = 0;
};

/// Charges the exact simulation of records of `rows` samples each on data
/// numbers of `bits`, with the convolutions of its z.
void charge_simulation(const Certificate& c, const std::vector<long>& rows, const DataBits& bits);

/// The estimate charge_simulation charges (operations).
double simulation_work(const Certificate& c, const std::vector<long>& rows, const DataBits& bits);

/// The bits of the numbers in the model's columns of `table` (scheduling
/// columns computed from the state are not in it), an upper bound read from
/// the text: 2·3.33 bits per character, plus the digits of a decimal exponent.
DataBits table_bits(const TextTable& table, const ColumnMap& columns);

/// The same of the exact u, y (signals) and ρ (scheduling).
DataBits experiment_bits(const Experiment<Rational>& exp);

}  // namespace lpvid
