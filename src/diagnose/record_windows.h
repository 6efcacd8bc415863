#pragma once
/// Bound windows over several estimation records (data/experiment.h:
/// records). A bound is one claim of Theorem 2.1 over several records (one
/// Δ, one noise bound; docs/several_records.md), so a bound window is a list
/// of row ranges, each inside ONE record, certified together:
///
///   default     with R > 1 records, window j is the j-th default window
///               (bound_windows.h: tile_windows of 200 rows) of every record
///               that has one: one claim per j over the records' j-th windows;
///   given       a window of the stacked rows (--window B:E) is cut at the
///               records' seams into its pieces, one per record it meets.
///
/// One record: every window is one piece, as before.
#include <vector>

#include "data/data_reference.h"
#include "diagnose/bound_windows.h"

namespace lpvid {

using JointWindow = std::vector<RowWindow>;  ///< row ranges of the stacked data, each inside one record

/// The joint windows of the stacked records of the given lengths
/// (Experiment::record_lengths(), at least one): `given` (each cut at the
/// seams) or, when empty, the default above.
std::vector<JointWindow> joint_windows(const std::vector<Eigen::Index>& lengths, const std::vector<RowWindow>& given);

/// The record (index into the lengths) that holds stacked row `row`, and its
/// first row; a row past the end is in the last record.
std::pair<size_t, Eigen::Index> record_of_row(const std::vector<Eigen::Index>& lengths, Eigen::Index row);

/// Where the stacked rows `piece` are in their file: the rows of the record
/// that holds them, as a window of that record's reference (`references[k]`:
/// record k's rows as read, one per record). No references (data made in
/// memory): a reference without a file whose rows are the stacked rows.
/// Throws InputError when the piece is not inside one record.
DataReference piece_reference(const std::vector<DataReference>& references, const std::vector<Eigen::Index>& lengths,
                              const RowWindow& piece);

}  // namespace lpvid
