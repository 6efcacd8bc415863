#pragma once
/// `lpvid compare --u COL... --y COL... --rho COL...`: the data columns that
/// play a model's input, output and scheduling columns, in the model's order.
/// The model file is not edited: the mapping renames, in memory, every place
/// where the model names a data column:
///
///   columns.u, columns.y          the data columns given (same count)
///   columns.rho                   with --rho: the data columns given for the
///                                 model's data-read scheduling columns (the
///                                 "@x<i>" state forms are the model's own and
///                                 keep their text); without --rho: a
///                                 scheduling column that is one of the model's
///                                 input or output columns follows that column
///                                 (diagnose schedules on the input, so a basis
///                                 "uEst^2" on the scheduling variable of column
///                                 uEst reads uVal after --u uVal)
///   units                         follow their column
///
/// Basis functions name scheduling variables (model "scheduling"), not data
/// columns, so they need no renaming: "uEst^2" stays the square of that
/// variable, which now reads the mapped column.

#include <string>
#include <vector>

#include "data/column_map.h"
#include "model/lpv_model.h"

namespace lpvid::cli {

struct ColumnMappingArgs {
  std::vector<std::string> u, y, rho;  ///< --u, --y, --rho (empty: not given)
  bool given() const { return !u.empty() || !y.empty() || !rho.empty(); }
};

/// The model with the mapping applied (model_path names it in messages).
/// Throws InputError naming the option when a count differs from the model's.
LpvModel<double> map_model_columns(const LpvModel<double>& model, const ColumnMappingArgs& a,
                                   const std::string& model_path);

/// Throws InputError naming the option (--u, --y or --rho) of the first
/// column it gives that `header` (the data file's column names) lacks.
void check_mapped_columns(const ColumnMappingArgs& a, const std::vector<std::string>& header,
                          const std::string& data_path);

}  // namespace lpvid::cli
