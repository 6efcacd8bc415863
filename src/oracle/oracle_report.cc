#include "oracle/oracle_report.h"

#include <cstdio>
#include <sstream>

#include "core/number_text.h"

namespace lpvid {

std::string survivor_list(const std::vector<std::string>& survivors) {
  std::string s;
  for (const std::string& p : survivors) s += (s.empty() ? "" : ", ") + p;
  return s;
}

OracleTotals totals_of(const std::vector<CaseReport>& cases) {
  OracleTotals t;
  for (const CaseReport& c : cases) {
    switch (c.judgement.verdict) {
      case OracleVerdict::kConfirmed: ++t.confirmed; break;
      case OracleVerdict::kRefuted: ++t.refuted; break;
      case OracleVerdict::kBadWitness: ++t.bad_witness; break;
      case OracleVerdict::kSuboptimal: ++t.suboptimal; break;
      case OracleVerdict::kUndecided: ++t.undecided; break;
      case OracleVerdict::kError: ++t.error; break;
      case OracleVerdict::kTampered: ++t.tampered; break;
    }
  }
  return t;
}

namespace {

std::string fixed(double x, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
  return buf;
}

std::string padded(std::string s, size_t width) {
  if (s.size() < width) s.append(width - s.size(), ' ');
  return s;
}

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // XML 1.0 forbids most control characters even escaped
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r') out += '?';
        else out += c;
    }
  }
  return out;
}

std::string totals_text(const OracleTotals& t) {
  return std::to_string(t.total()) + " cases: " + std::to_string(t.confirmed) + " confirmed, " + std::to_string(t.refuted) +
         " refuted, " + std::to_string(t.bad_witness) + " bad_witness, " + std::to_string(t.suboptimal) + " suboptimal, " +
         std::to_string(t.undecided) + " undecided, " + std::to_string(t.error) + " error, " + std::to_string(t.tampered) +
         " tampered";
}

/// identify: L_class, its certificate and region, or why there is none.
nlohmann::ordered_json class_lower_end_json(const ClassReference& k) {
  nlohmann::ordered_json j{{"verified", k.verified}};
  if (!k.verified) {
    j["reason"] = k.reason;
    return j;
  }
  j["lower_dmax2"] = CGAL::to_double(k.lower);
  j["lower_exact"] = exact_decimal_or_fraction(k.lower);
  j["certificate"] = k.certificate;
  j["region"] = k.whole_class ? "whole_class" : "box";
  return j;
}

}  // namespace

std::string case_table(const std::vector<CaseReport>& cases) {
  std::ostringstream o;
  o << padded("case", 11) << padded("task", 10) << padded("n  ny x nu", 12) << padded("claim", 42) << padded("verdict", 12)
    << "outside s  lpvid s  certificate\n";
  for (const CaseReport& c : cases) {
    const std::string size = std::to_string(c.n) + "  " + std::to_string(c.ny) + " x " + std::to_string(c.nu);
    // the certificate relative to the run's folder (the case folder's parent)
    std::string evidence = c.judgement.evidence;
    const std::string parent = c.folder.substr(0, c.folder.size() - c.name.size());
    if (!parent.empty() && evidence.rfind(parent, 0) == 0) evidence = evidence.substr(parent.size());
    o << padded(c.name, 11) << padded(to_string(c.kind), 10) << padded(size, 12) << padded(c.claim, 42)
      << padded(to_string(c.judgement.verdict), 12) << padded(fixed(c.outside_seconds, 2), 11)
      << padded(fixed(c.lpvid_seconds, 2), 9) << evidence << "\n";
  }
  o << totals_text(totals_of(cases)) << "\n";
  return o.str();
}

nlohmann::ordered_json oracle_report_json(const std::vector<CaseReport>& cases, const std::string& command, double seconds,
                                          bool strict) {
  nlohmann::ordered_json j;
  j["format"] = "lpvid-oracle-report/1";
  j["command"] = command;
  j["seconds"] = seconds;
  j["strict"] = strict;
  const OracleTotals t = totals_of(cases);
  j["totals"] = {{"cases", t.total()},           {"confirmed", t.confirmed},   {"refuted", t.refuted},
                 {"bad_witness", t.bad_witness}, {"suboptimal", t.suboptimal}, {"undecided", t.undecided},
                 {"error", t.error},             {"tampered", t.tampered}};
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const CaseReport& c : cases) {
    nlohmann::ordered_json e;
    e["case"] = c.name;
    e["folder"] = c.folder;
    e["task"] = to_string(c.kind);
    e["n"] = c.n;
    e["inputs"] = c.nu;
    e["outputs"] = c.ny;
    e["claim"] = c.claim;
    if (c.judgement.claimed) e["claimed_objective"] = exact_decimal_or_fraction(*c.judgement.claimed);
    e["verdict"] = to_string(c.judgement.verdict);
    e["reason"] = c.judgement.reason;
    if (!c.judgement.evidence.empty()) {
      e["certificate"] = c.judgement.evidence;
      e["certificate_check"] = c.evidence_check;
    }
    if (c.klass) e["class_lower_end"] = class_lower_end_json(*c.klass);
    e["outside_seconds"] = c.outside_seconds;
    e["outside_exit"] = c.outside_exit;
    e["outside_log"] = c.outside_log;
    e["survivors"] = c.survivors;
    e["lpvid_seconds"] = c.lpvid_seconds;
    list.push_back(e);
  }
  j["cases"] = list;
  return j;
}

std::string junit_xml(const std::vector<CaseReport>& cases, double seconds, bool strict) {
  const OracleTotals t = totals_of(cases);
  const int failures = t.refuted + t.bad_witness + (strict ? t.suboptimal : 0), errors = t.error + t.tampered;
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<testsuites name=\"lpvid oracle\" tests=\"" << t.total() << "\" failures=\"" << failures << "\" errors=\"" << errors
    << "\" skipped=\"" << t.undecided << "\" time=\"" << fixed(seconds, 3) << "\">\n"
    << "  <testsuite name=\"lpvid-oracle\" tests=\"" << t.total() << "\" failures=\"" << failures << "\" errors=\"" << errors
    << "\" skipped=\"" << t.undecided
    << "\" time=\"" << fixed(seconds, 3) << "\">\n";
  for (const CaseReport& c : cases) {
    const std::string check = c.evidence_check.empty() ? "" : " (lpvid-verify: " + c.evidence_check + ")";
    const std::string detail =
        c.claim + ": " + c.judgement.reason + (c.judgement.evidence.empty() ? "" : "\ncertificate: " + c.judgement.evidence + check);
    o << "    <testcase classname=\"lpvid.oracle." << to_string(c.kind) << "\" name=\"" << xml_escape(c.name) << "\" time=\""
      << fixed(c.outside_seconds, 3) << "\">\n";
    switch (c.judgement.verdict) {
      case OracleVerdict::kRefuted:
      case OracleVerdict::kBadWitness:
        o << "      <failure type=\"" << to_string(c.judgement.verdict) << "\" message=\"" << xml_escape(c.judgement.reason)
          << "\">" << xml_escape(detail) << "</failure>\n";
        break;
      case OracleVerdict::kSuboptimal:
        if (strict)
          o << "      <failure type=\"suboptimal\" message=\"" << xml_escape(c.judgement.reason) << "\">" << xml_escape(detail)
            << "</failure>\n";
        else
          o << "      <system-out>suboptimal: " << xml_escape(detail) << "</system-out>\n";
        break;
      case OracleVerdict::kError:
      case OracleVerdict::kTampered:
        o << "      <error type=\"" << (c.judgement.verdict == OracleVerdict::kError ? "no answer" : "tampered")
          << "\" message=\"" << xml_escape(c.judgement.reason) << "\">" << xml_escape(detail)
          << "\nlog: " << xml_escape(c.outside_log) << "</error>\n";
        break;
      case OracleVerdict::kUndecided:
        o << "      <skipped message=\"" << xml_escape(c.judgement.reason) << "\"/>\n";
        break;
      case OracleVerdict::kConfirmed:
        o << "      <system-out>" << xml_escape(detail) << "</system-out>\n";
        break;
    }
    o << "    </testcase>\n";
  }
  o << "  </testsuite>\n</testsuites>\n";
  return o.str();
}

}  // namespace lpvid
