/// Properties of the model file reader/writer (docs/design.md §11.1): exact round trips
/// for Rational and double models, numbers in every text form read exactly,
/// and corrupted files either read (to a model the writer accepts) or throw
/// InputError, never anything else (run under ASan/UBSan).

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/input_error.h"
#include "model/model_file.h"
#include "support/generators.h"

namespace lpvid {
namespace {

namespace gf = gen::files;

RC_GTEST_PROP(ModelFileProperty, RationalModelWriteReadIsExact, ()) {
  const LpvModel<Rational> m = *gf::file_model<Rational>(gf::file_rational());
  const std::string text = write_model_json(m);
  const LpvModel<Rational> back = parse_model_json<Rational>(text, "gen.json");
  RC_ASSERT(gf::same_model(back, m));
  RC_ASSERT(write_model_json(back) == text);
}

RC_GTEST_PROP(ModelFileProperty, DoubleModelWriteReadIsExact, ()) {
  const LpvModel<double> m = *gf::file_model<double>(gf::file_double());
  const std::string text = write_model_json(m);
  RC_ASSERT(gf::same_model(parse_model_json<double>(text, "gen.json"), m));
}

RC_GTEST_PROP(ModelFileProperty, EveryNumberFormReadsExactly, ()) {
  const gf::ModelText mt = *gf::model_text();
  const LpvModel<Rational> m = parse_model_json<Rational>(mt.text, "gen.json");
  RC_ASSERT(gf::same_model(m, mt.model));
  // The double reader agrees with rounding each exact number once, e.g. x0.
  const LpvModel<double> d = parse_model_json<double>(mt.text, "gen.json");
  for (Eigen::Index i = 0; i < m.x0.size(); ++i) RC_ASSERT(d.x0(i) == nearest_double(m.x0(i)));
}

/// Reads a possibly corrupted model both ways; only InputError may escape,
/// and a model that reads must write and read back to the same model.
template <typename T>
void read_or_input_error(const std::string& text) {
  LpvModel<T> m;
  try {
    m = parse_model_json<T>(text, "bad.json");
  } catch (const InputError&) {
    RC_TAG("InputError");
    return;
  }
  RC_TAG("reads");
  const std::string again = write_model_json(m);
  RC_ASSERT(gf::same_model(parse_model_json<T>(again, "again.json"), m));
}

RC_GTEST_PROP(ModelFileProperty, CorruptedFileReadsOrThrowsInputError, ()) {
  const gf::ModelText mt = *gf::model_text();
  const std::string bad = *gf::corrupted(mt.text);
  read_or_input_error<Rational>(bad);
  read_or_input_error<double>(bad);
}

RC_GTEST_PROP(ModelFileProperty, CorruptedWrittenFileReadsOrThrowsInputError, ()) {
  const std::string text = write_model_json(*gf::file_model<Rational>(gf::file_rational()));
  const std::string bad = *gf::corrupted(text);
  read_or_input_error<Rational>(bad);
  read_or_input_error<double>(bad);
}

RC_GTEST_PROP(ModelFileProperty, ArbitraryBytesReadOrThrowInputError, (const std::string& text)) {
  read_or_input_error<Rational>(text);
  read_or_input_error<double>(text);
}

}  // namespace
}  // namespace lpvid
