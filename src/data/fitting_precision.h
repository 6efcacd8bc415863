#pragma once
/// The precision at which lpvid's CHOICES read measured data.
///
/// The fits behind a choice (fit-linear's order, diagnose's effects, starts
/// and folds) are minimisations of a free-run error over a non-smooth,
/// many-basined landscape: a change of the data in its last binary digit can
/// steer a Levenberg–Marquardt path into another basin and so change the
/// model chosen. Those fits therefore read every sample rounded to
/// kFittingDigits significant decimal digits (correctly rounded, half to
/// even), far below any measurement's resolution (the cascaded tanks record
/// has 5 digits, a 24-bit converter about 7). A sample written with fewer
/// digits is unchanged by it, and the same sample moved by one unit in the
/// last place, or re-saved by another number printer with at least
/// kFittingDigits digits, reads as the same number: the same data gives the
/// same choice.
///
/// What is certified is not rounded: certificates read the data's text
/// exactly (Experiment<Rational>), and the bounds are of the data as written.

#include "data/experiment.h"

namespace lpvid {

/// Significant decimal digits of a sample as the fits read it.
inline constexpr int kFittingDigits = 10;

/// x correctly rounded to kFittingDigits significant decimal digits (the
/// nearest double to that decimal); 0, ±inf, NaN and a value whose rounded
/// decimal is beyond the largest double (|x| > 1.797693134e308) unchanged.
/// Idempotent.
double at_fitting_precision(double x);

/// Every sample of u, y, ρ and every record's x0 at_fitting_precision;
/// records and source kept.
Experiment<double> at_fitting_precision(const Experiment<double>& e);

}  // namespace lpvid
