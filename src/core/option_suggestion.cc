#include "core/option_suggestion.h"

#include <algorithm>

namespace lpvid {

namespace {

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// The command path the parse reached ("jobs plan"), below `root`.
std::string parsed_path(const CLI::App& app, const std::string& root) {
  std::string path = root;
  const CLI::App* at = &app;
  for (bool deeper = true; deeper;) {
    deeper = false;
    for (const CLI::App* sub : at->get_subcommands())
      if (!sub->get_name().empty()) {
        path += (path.empty() ? "" : " ") + sub->get_name();
        at = sub;
        deeper = true;
        break;
      }
  }
  return path;
}

std::vector<std::string> long_names(const OptionTable& table, const std::string& path) {
  std::vector<std::string> names;
  const auto it = table.find(path);
  if (it == table.end()) return names;
  for (const OptionInfo& o : it->second)
    if (!o.positional)
      for (const std::string& n : o.names) names.push_back("--" + n);
  return names;
}

}  // namespace

std::string closest_option(const std::string& word, const std::vector<std::string>& names) {
  std::string best;
  size_t best_distance = 0;
  for (const std::string& n : names) {
    const size_t d = edit_distance(word, n);
    const size_t allowed = std::max<size_t>(2, std::max(word.size(), n.size()) / 4);
    if (d <= allowed && (best.empty() || d < best_distance)) {
      best = n;
      best_distance = d;
    }
  }
  return best;
}

int print_option_suggestions(const CLI::App& app, const OptionTable& table, const std::string& root,
                             const std::vector<std::string>& args, std::ostream& err) {
  const std::string path = parsed_path(app, root);
  std::vector<std::string> names = long_names(table, path);
  if (path != root) {
    const std::vector<std::string> top = long_names(table, root);  // the limits are taken after the command too
    names.insert(names.end(), top.begin(), top.end());
  }
  int printed = 0;
  for (const std::string& arg : args) {
    if (arg.rfind("--", 0) != 0 || arg.size() < 3) continue;
    const std::string word = arg.substr(0, arg.find('='));
    if (std::find(names.begin(), names.end(), word) != names.end()) continue;
    const std::string suggestion = closest_option(word, names);
    if (suggestion.empty()) continue;
    const std::string program = root.empty() ? "lpvid" : root;
    err << (path.empty() ? program : root.empty() ? program + " " + path : path) << ": unknown option " << word
        << "; did you mean " << suggestion << "?\n";
    ++printed;
  }
  return printed;
}

}  // namespace lpvid
