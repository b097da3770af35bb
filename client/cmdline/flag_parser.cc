#include "cmdline/flag_parser.h"

#include <cstdint>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"

namespace getme::cmdline {

absl::Status ParseFlags(const std::vector<std::string>& args, const FlagTable& flags,
                        const ParseRules& rules, bool& help) {
  bool only_positionals = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (only_positionals || arg.size() < 2 || arg[0] != '-') {
      if (absl::Status status = rules.positional(arg); !status.ok()) return status;
      continue;
    }
    if (rules.equals_and_double_dash && arg == "--") {
      only_positionals = true;
      continue;
    }
    if (arg == "-h" || arg == "--help") {
      help = true;
      if (rules.help_ends_parse) return absl::OkStatus();
      continue;
    }
    const std::size_t equals = rules.equals_and_double_dash ? arg.find('=') : std::string::npos;
    const std::string name = arg.substr(0, equals);
    FlagSpec spec;
    if (const auto flag = flags.find(name); flag != flags.end()) {
      spec = flag->second;
    } else {
      absl::StatusOr<FlagSpec> unknown = rules.unknown(name);
      if (!unknown.ok()) return unknown.status();
      spec = *std::move(unknown);
    }
    std::string value;
    if (spec.takes_value) {
      if (equals != std::string::npos) {
        value = arg.substr(equals + 1);
      } else if (i + 1 < args.size()) {
        value = args[++i];
      } else {
        return absl::InvalidArgumentError(absl::StrCat(rules.flag_prefix, name, " needs a value"));
      }
    } else if (equals != std::string::npos) {
      return absl::InvalidArgumentError(absl::StrCat(rules.flag_prefix, name, " takes no value"));
    }
    if (absl::Status status = spec.apply(value); !status.ok()) return status;
  }
  return absl::OkStatus();
}

FlagAction SetTrue(bool& target) {
  return [&target](const std::string&) {
    target = true;
    return absl::OkStatus();
  };
}

FlagAction StringFlag(std::string& target) {
  return [&target](const std::string& value) {
    target = value;
    return absl::OkStatus();
  };
}

template <typename Int>
FlagAction IntegerFlag(absl::string_view name, Int& target, Int min, Int max) {
  return [name = std::string(name), &target, min, max](const std::string& value) {
    Int parsed = 0;
    if (!absl::SimpleAtoi(value, &parsed) || parsed < min || parsed > max) {
      return absl::InvalidArgumentError(absl::StrCat("option ", name, " expects an integer in [",
                                                     min, ", ", max, "], got '", value, "'"));
    }
    target = parsed;
    return absl::OkStatus();
  };
}

template FlagAction IntegerFlag<int>(absl::string_view, int&, int, int);
template FlagAction IntegerFlag<std::int64_t>(absl::string_view, std::int64_t&, std::int64_t,
                                              std::int64_t);

}  // namespace getme::cmdline
