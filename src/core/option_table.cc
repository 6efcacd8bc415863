#include "core/option_table.h"

namespace lpvid {

namespace {

OptionInfo option_info(const CLI::Option& o) {
  OptionInfo info;
  info.positional = !o.nonpositional();
  if (info.positional)
    info.names = {o.get_name(true)};
  else
    info.names = o.get_lnames();
  info.flag = o.get_expected_max() == 0 || o.get_type_size_max() == 0;  // add_flag: expected(0)
  const CLI::MultiOptionPolicy policy = o.get_multi_option_policy();
  info.multi = !info.flag && (o.get_items_expected_max() > 1 || policy == CLI::MultiOptionPolicy::TakeAll ||
                              policy == CLI::MultiOptionPolicy::Join);
  info.required = o.get_required();
  info.help = o.get_description();
  return info;
}

bool is_help_or_version(const CLI::Option& o) {
  for (const std::string& n : o.get_lnames())
    if (n == "help" || n == "help-all" || n == "version") return true;
  return false;
}

/// The options of `app` and of its option groups (nameless subcommands);
/// hidden ones (group "": refused aliases, cli/refused_alias.h) work for
/// nothing and are left out.
void add_own_options(const CLI::App& app, std::vector<OptionInfo>& out) {
  for (const CLI::Option* o : app.get_options())
    if (!is_help_or_version(*o) && !o->get_group().empty() && (o->nonpositional() || !o->get_name(true).empty()))
      out.push_back(option_info(*o));
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->get_name().empty()) add_own_options(*sub, out);
}

}  // namespace

void add_option_table(const CLI::App& app, const std::string& path, OptionTable& out) {
  add_own_options(app, out[path]);
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (!sub->get_name().empty())
      add_option_table(*sub, path.empty() ? sub->get_name() : path + " " + sub->get_name(), out);
}

}  // namespace lpvid
