#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"

namespace getme::cmdline {

// The argument parsing of getme's programs (the `getme` commands, getme-bench): a table of flags,
// each with what it does with its value, walked by one function.

// What a flag does with its value ("" for a flag without one); an error ends the parse.
using FlagAction = std::function<absl::Status(const std::string& value)>;

// A flag: whether it takes a value, and what to do with it.
struct FlagSpec {
  bool takes_value;
  FlagAction apply;
};

// Flags by name, spelled as on the command line ("--threads", "-o").
using FlagTable = std::map<std::string, FlagSpec>;

// How a program reads its command line.
struct ParseRules {
  // What to do with an argument that is not a flag: "-", or anything not starting with '-'.
  std::function<absl::Status(const std::string& argument)> positional;
  // What to do with a flag the table does not hold: an error, or the spec to read it by.
  std::function<absl::StatusOr<FlagSpec>(const std::string& name)> unknown;
  // "--name=value" is a flag with its value, and after "--" every argument is a positional.
  bool equals_and_double_dash = true;
  // "-h" / "--help" ends the parse (what follows is not read); else it is noted and parsing goes
  // on.
  bool help_ends_parse = false;
  // How messages name a flag: "option --bins needs a value".
  absl::string_view flag_prefix = "option ";
};

// Walks `args` (the arguments after the program or command name) in order: each flag's action
// runs as it is met, a flag's value is the next argument (whatever it looks like) or, with
// equals_and_double_dash, the text after '='. `help` is set by "-h" / "--help". The first error
// (from an action, `rules`, or a missing or unexpected value) is returned.
absl::Status ParseFlags(const std::vector<std::string>& args, const FlagTable& flags,
                        const ParseRules& rules, bool& help);

// Actions for the common kinds of flags.
FlagAction SetTrue(bool& target);
FlagAction StringFlag(std::string& target);
// An integer in [min, max], else "option NAME expects an integer in [min, max], got 'VALUE'".
template <typename Int>
FlagAction IntegerFlag(absl::string_view name, Int& target, Int min, Int max);

}  // namespace getme::cmdline
