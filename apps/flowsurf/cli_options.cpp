#include "cli_options.h"

#include <cmath>

namespace flowsurf::app {

void addRenderOptions(CLI::App& cmd, RenderOptions& o) {
    for (const OptionSpec& spec : renderOptionTable()) {
        const OptionSpec* s = &spec;
        if (s->takes(FrontEnd::Positional)) {
            cmd.add_option_function<std::string>(s->name, [&o, s](const std::string& v) { s->set(o, v); }, s->help);
            continue;
        }
        if (!s->takes(FrontEnd::CommandLine)) continue;
        std::string names = (s->shortName.empty() ? "" : "-" + s->shortName + ",") + "--" + s->name;
        std::string help = s->help;
        if (s->kind == OptionKind::Choice) {
            std::string list;
            for (const auto& c : s->choices) list += (list.empty() ? "" : "|") + c;
            help += " [" + list + "]";
        } else if (s->kind == OptionKind::Int || s->kind == OptionKind::Float || s->kind == OptionKind::Size) {
            auto bound = [](double v) {
                return v == std::floor(v) && std::abs(v) < 1e15 ? std::to_string(static_cast<long long>(v))
                                                                 : formatDouble(v);
            };
            help += s->max >= 1e29 ? " [>= " + bound(s->min) + "]" : " [" + bound(s->min) + ".." + bound(s->max) + "]";
        }
        if (std::string d = defaultText(*s); !d.empty() && s->kind != OptionKind::Flag) help += " (default " + d + ")";
        CLI::Option* opt = nullptr;
        if (s->kind == OptionKind::Flag)
            opt = cmd.add_flag_callback(names, [&o, s] { s->set(o, "true"); }, help);
        else if (s->repeatable)
            opt = cmd.add_option_function<std::vector<std::string>>(
                     names,
                     [&o, s](const std::vector<std::string>& v) {
                         std::string joined;
                         for (const auto& item : v) joined += (joined.empty() ? "" : ";") + item;
                         s->set(o, joined);
                     },
                     help)
                      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
        else
            opt = cmd.add_option_function<std::string>(names, [&o, s](const std::string& v) { s->set(o, v); }, help);
        static const char* const kTypeNames[] = {"", "INT", "FLOAT", "TEXT", "CHOICE", "WxH", "X,Y,Z", "COLOR", "PATH"};
        static_assert(std::size(kTypeNames) == session::kOptionKinds, "one type name per OptionKind");
        opt->group(groupName(s->role.group))->type_name(kTypeNames[int(s->kind)]);
    }
    cmd.add_flag("--list-builtins", o.listBuiltins, "List the built-in scenes and exit");
}

}  // namespace flowsurf::app
