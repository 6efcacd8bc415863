#pragma once
/// From a text table to an Experiment (docs/design.md §4): the model's `columns`
/// (docs/design.md §11.1) name which columns hold u, y and ρ; each cell of a used column
/// is read in the scalar T (double: nearest double; Rational: exactly, so
/// "0.1" is 1/10).

#include <string>
#include <vector>

#include "data/experiment.h"
#include "data/column_map.h"

namespace lpvid {

/// Builds the n × nu, n × ny, n × nρ matrices from the named columns
/// (n = number of data rows; a list in `columns` may be empty, giving a
/// matrix with 0 columns). A column may be used more than once. Unused
/// columns are not read (they may hold anything, e.g. the mostly empty `Ts`).
///
/// Throws InputError:
///  - "file: no data rows" for a table without rows;
///  - "file: column 'x' not found (available: 'a', 'b', ...)" for an unknown name;
///  - "file:line: column 'yEst': 'abc' is not a number" for an empty cell,
///    NaN, inf, text or (double only) a value that overflows a double.
template <typename T>
Experiment<T> make_experiment(const TextTable& table, const ColumnMap& columns);

/// Rows [begin, end) of an experiment (0 <= begin <= end <= n), e.g. an
/// estimation/validation split. Throws InputError naming the source if the
/// range is out of bounds. Stacked records keep their parts inside the window.
template <typename T>
Experiment<T> select_rows(const Experiment<T>& exp, Eigen::Index begin, Eigen::Index end);

/// Rows [begin, end) of a text table (0 <= begin <= end <= rows), each with
/// its file line: make_experiment on it reads only the cells of those rows
/// (a window of a long record converts 200 rows, not the whole file, and a
/// cell outside the window is never looked at). Throws InputError naming the
/// file if the range is out of bounds.
TextTable select_table_rows(const TextTable& table, long begin, long end);

/// Several experiments of one system (same columns) stacked row-wise as
/// records (data/experiment.h: records); one part: that experiment. The
/// source names them all. Throws InputError when the columns differ.
template <typename T>
Experiment<T> stack_records(const std::vector<Experiment<T>>& parts);

extern template Experiment<double> make_experiment<double>(const TextTable&, const ColumnMap&);
extern template Experiment<Rational> make_experiment<Rational>(const TextTable&, const ColumnMap&);
extern template Experiment<double> select_rows<double>(const Experiment<double>&, Eigen::Index, Eigen::Index);
extern template Experiment<Rational> select_rows<Rational>(const Experiment<Rational>&, Eigen::Index,
                                                           Eigen::Index);

}  // namespace lpvid

namespace lpvid {
extern template Experiment<double> stack_records<double>(const std::vector<Experiment<double>>&);
extern template Experiment<Rational> stack_records<Rational>(const std::vector<Experiment<Rational>>&);
}  // namespace lpvid
