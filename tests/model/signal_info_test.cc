// Sample time and units in the model file (data/signal_info.h): read,
// checked against the model's columns, written back unchanged, and absent
// from files that do not give them.
#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"
#include "model/model_file.h"

namespace lpvid {
namespace {

std::string described_model(const std::string& extra) {
  return R"({"format": "lpvid-model/1", "states": 1, "inputs": 1, "outputs": 1, "scheduling": ["p"],
  "columns": {"u": ["pump"], "y": ["level"], "rho": ["p"]},
  "initial": {"A": [{"basis": "1", "value": [[0.5]]}], "B": [{"basis": "1", "value": [[1]]}],
              "C": [{"basis": "1", "value": [[1]]}]})" +
         extra + "}";
}

TEST(SignalInfo, ReadWrittenAndReadAgain) {
  const auto m = parse_model_json<Rational>(described_model(R"(, "sample_time": 4, "units": {"pump": "V", "level": "cm"})"), "m.json");
  EXPECT_EQ(m.signal_info.sample_time, 4.0);
  EXPECT_EQ(m.signal_info.unit_of("pump"), "V");
  EXPECT_EQ(m.signal_info.unit_of("level"), "cm");
  EXPECT_EQ(m.signal_info.unit_of("p"), "");
  EXPECT_EQ(m.signal_info.label("level"), "level [cm]");
  EXPECT_DOUBLE_EQ(m.signal_info.time_of(3), 12.0);
  const auto again = parse_model_json<double>(write_model_json(m), "again.json");
  EXPECT_EQ(again.signal_info.sample_time, 4.0);
  EXPECT_EQ(again.signal_info.units, m.signal_info.units);
  // an exact fraction is a legal number text; 0.08 s stays 0.08 in double
  EXPECT_DOUBLE_EQ(parse_model_json<double>(described_model(R"(, "sample_time": "2/25")"), "m").signal_info.sample_time, 0.08);
}

TEST(SignalInfo, AbsentMeansSamplesAndNothingWritten) {
  const auto m = parse_model_json<double>(described_model(""), "m.json");
  EXPECT_TRUE(m.signal_info.empty());
  EXPECT_EQ(m.signal_info.time_label(), "sample");
  EXPECT_DOUBLE_EQ(m.signal_info.time_of(3), 3.0);
  const std::string text = write_model_json(m);
  EXPECT_EQ(text.find("sample_time"), std::string::npos);
  EXPECT_EQ(text.find("units"), std::string::npos);
}

TEST(SignalInfo, BadValuesAreRefusedWithTheirPath) {
  const auto message = [](const std::string& extra) {
    try {
      parse_model_json<double>(described_model(extra), "m.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(R"(, "sample_time": 0)").find("sample_time"), std::string::npos);
  EXPECT_NE(message(R"(, "sample_time": -1)").find("positive"), std::string::npos);
  EXPECT_NE(message(R"(, "sample_time": "fast")").find("sample_time"), std::string::npos);
  EXPECT_NE(message(R"(, "units": {"flow": "V"})").find("not one of the model's columns"), std::string::npos);
  EXPECT_NE(message(R"(, "units": {"pump": 3})").find("units.pump"), std::string::npos);
  EXPECT_NE(message(R"(, "units": ["V"])").find("units"), std::string::npos);
}

}  // namespace
}  // namespace lpvid
