#pragma once
/// The several-record part of a report (docs/several_records.md): the
/// "records" list and the readable table of certify/record_figures.h's
/// figures, one line per record and a pooled line.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "certify/record_figures.h"
#include "data/data_reference.h"

namespace lpvid::cli {

/// The report's "records" list: file, rows [b, e] or null, sha256, samples
/// and the figures of each record (refs and t.records in the same order).
nlohmann::ordered_json records_json(const std::vector<DataReference>& refs, const RecordTable& t);

/// The readable table: one line per record and a "pooled" line.
std::string records_text(const std::vector<DataReference>& refs, const RecordTable& t);

/// Adds the records list and the pooled figures ("records", "records_pooled")
/// to `report` and returns the readable table; nothing for one record (its
/// report is the one-record report).
std::string add_record_figures(nlohmann::ordered_json& report, const std::vector<DataReference>& refs,
                               const LpvModel<double>& model, const Experiment<double>& exp, const CertifiedBounds& b);

}  // namespace lpvid::cli
