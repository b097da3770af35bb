#include "bench_options.h"

#include <filesystem>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/strings/str_replace.h"
#include "absl/strings/str_split.h"
#include "cmdline/flag_parser.h"

namespace getme::bench {

const char kBenchUsage[] = R"(Usage: getme-bench [options]
Smooths each mesh with each method, REPEATS times per thread count, and prints a Markdown table
of medians (min–max). With --out, writes one JSON file per (mesh, method, threads, mode) with
every repeat, and the per-iteration trace of the median repeat as JSON lines (`getme report
--trace` draws it).

Meshes (repeatable, at least one):
  --mesh PATH             a mesh file (.vtk, .vtu, .msh, .mesh)
  --generate "KIND ARGS"  a getme-meshgen mesh without OUT, e.g. "hybrid --size 20 --seed 1"
  --name NAME             the name of the mesh named just before (default: file stem, or the
                          generator arguments joined by '-')
Runs:
  --methods LIST          comma-separated (default smart-laplace,simultaneous,sequential,getme,
                          warpage)
  --threads LIST          comma-separated engine thread counts (default 1)
  --repeats N             runs per measurement; the median is reported (default 3)
  --free-boundary         boundary nodes may move (nodes marked `fixed` stay)
  --literal               the paper's algorithm, safeguards off (as `getme smooth --literal`)
  --no-polish             end --method getme after the sequential substep (no polish stage)
  --max-iterations N      cap every phase at N iterations (sequential: picks)
  --sequential-batch N    sequential picks per batch (as `getme smooth`; 1 = the paper's one
                          pick at a time)
  --kernel-lanes N         doubles per vector in the element passes: 2 (the reference), 4
                          (AVX2) or 8 (AVX-512); default: the widest this machine runs. In-process
                          runs only (a server uses its own widest)
  --target-q-mean Q       also report the time until q_mean first reaches Q
Output:
  --out DIR               JSON per measurement and traces into DIR (created)
  --write-meshes          also write DIR/<mesh>.vtk (generated meshes) and
                          DIR/<mesh>.<method>.t<threads>.vtk (smoothed), for `getme report`
Service overhead:
  --service               run each measurement also through a getme-server on loopback
  --server HOST:PORT      use this running server instead of starting one
  --server-binary PATH    the getme-server to start (default: beside getme-bench)
)";

namespace {

absl::StatusOr<std::vector<int>> ParseIntList(const std::string& flag, const std::string& value,
                                              int min) {
  std::vector<int> values;
  for (const absl::string_view part : absl::StrSplit(value, ',')) {
    int parsed = 0;
    if (!absl::SimpleAtoi(part, &parsed) || parsed < min) {
      return absl::InvalidArgumentError(
          absl::StrCat(flag, ": '", value, "' is not a list of integers >= ", min));
    }
    values.push_back(parsed);
  }
  return values;
}

absl::StatusOr<std::vector<Method>> ParseMethodList(const std::string& value) {
  std::vector<Method> methods;
  for (const absl::string_view part : absl::StrSplit(value, ',')) {
    absl::StatusOr<Method> method = ParseMethod(std::string_view(part.data(), part.size()));
    if (!method.ok())
      return absl::InvalidArgumentError(absl::StrCat("--methods: ", method.status().message()));
    methods.push_back(*method);
  }
  return methods;
}

// "hybrid --size 20 --seed 1" → "hybrid-size-20-seed-1": readable and safe as a file name.
std::string GeneratorName(const std::string& arguments) {
  std::vector<std::string> words = absl::StrSplit(arguments, ' ', absl::SkipWhitespace());
  for (std::string& word : words) {
    while (word.starts_with("-")) word.erase(0, 1);
    word = absl::StrReplaceAll(word, {{"/", "_"}, {",", "x"}});
  }
  return absl::StrJoin(words, "-");
}

}  // namespace

absl::StatusOr<BenchOptions> ParseBenchOptions(const std::vector<std::string>& args) {
  BenchOptions options;
  const cmdline::FlagTable flags = {
      {"--free-boundary", {false, cmdline::SetTrue(options.free_boundary)}},
      {"--literal", {false, cmdline::SetTrue(options.literal)}},
      {"--no-polish", {false, cmdline::SetTrue(options.no_polish)}},
      {"--write-meshes", {false, cmdline::SetTrue(options.write_meshes)}},
      {"--service", {false, cmdline::SetTrue(options.service)}},
      {"--mesh",
       {true,
        [&](const std::string& value) {
          options.meshes.push_back(
              {MeshSpec::Source::kFile, value, std::filesystem::path(value).stem().string()});
          return absl::OkStatus();
        }}},
      {"--generate",
       {true,
        [&](const std::string& value) {
          options.meshes.push_back({MeshSpec::Source::kGenerator, value, GeneratorName(value)});
          return absl::OkStatus();
        }}},
      {"--name",
       {true,
        [&](const std::string& value) {
          if (options.meshes.empty()) {
            return absl::InvalidArgumentError(
                "--name must follow the --mesh or --generate it names");
          }
          options.meshes.back().name = value;
          return absl::OkStatus();
        }}},
      {"--methods",
       {true,
        [&](const std::string& value) -> absl::Status {
          absl::StatusOr<std::vector<Method>> methods = ParseMethodList(value);
          if (!methods.ok()) return methods.status();
          options.methods = *std::move(methods);
          return absl::OkStatus();
        }}},
      {"--threads",
       {true,
        [&](const std::string& value) -> absl::Status {
          absl::StatusOr<std::vector<int>> threads = ParseIntList("--threads", value, 1);
          if (!threads.ok()) return threads.status();
          options.thread_counts = *std::move(threads);
          return absl::OkStatus();
        }}},
      {"--repeats",
       {true,
        [&](const std::string& value) -> absl::Status {
          absl::StatusOr<std::vector<int>> repeats = ParseIntList("--repeats", value, 1);
          if (!repeats.ok()) return repeats.status();
          if (repeats->size() != 1) return absl::InvalidArgumentError("--repeats takes one number");
          options.repeats = repeats->front();
          return absl::OkStatus();
        }}},
      {"--max-iterations",
       {true,
        [&](const std::string& value) {
          std::int64_t cap = 0;
          if (!absl::SimpleAtoi(value, &cap) || cap < 1) {
            return absl::InvalidArgumentError(
                absl::StrCat("--max-iterations: '", value, "' is not an integer >= 1"));
          }
          options.max_iterations = cap;
          return absl::OkStatus();
        }}},
      {"--sequential-batch",
       {true, cmdline::IntegerFlag<std::int64_t>("--sequential-batch", options.sequential_batch, 1,
                                                 65536)}},
      {"--kernel-lanes",
       {true,
        [&](const std::string& value) {
          int lanes = 0;
          if (!absl::SimpleAtoi(value, &lanes) || (lanes != 2 && lanes != 4 && lanes != 8)) {
            return absl::InvalidArgumentError(
                absl::StrCat("--kernel-lanes: '", value, "' is not 2, 4 or 8"));
          }
          options.kernel_lanes = lanes;
          return absl::OkStatus();
        }}},
      {"--target-q-mean",
       {true,
        [&](const std::string& value) {
          double target = 0.0;
          if (!absl::SimpleAtod(value, &target) || !(target >= 0.0 && target <= 1.0)) {
            return absl::InvalidArgumentError(
                absl::StrCat("--target-q-mean: '", value, "' is not a number in [0, 1]"));
          }
          options.target_q_mean = target;
          return absl::OkStatus();
        }}},
      {"--out", {true, cmdline::StringFlag(options.out_dir)}},
      {"--server",
       {true,
        [&](const std::string& value) {
          options.server = value;
          options.service = true;
          return absl::OkStatus();
        }}},
      {"--server-binary", {true, cmdline::StringFlag(options.server_binary)}},
  };
  // getme-bench's own spelling: no "--name=value" or "--"; --help ends the parse; every argument
  // is a flag, and a "--" word the table does not know is read with its value, then refused.
  cmdline::ParseRules rules;
  rules.equals_and_double_dash = false;
  rules.help_ends_parse = true;
  rules.flag_prefix = "";
  const auto unexpected = [](const std::string& argument) {
    return absl::InvalidArgumentError(
        absl::StrCat("unexpected argument '", argument, "'; meshes are given with --mesh PATH"));
  };
  rules.positional = unexpected;
  rules.unknown = [&](const std::string& name) -> absl::StatusOr<cmdline::FlagSpec> {
    if (!name.starts_with("--")) return unexpected(name);
    return cmdline::FlagSpec{
        true, [name](const std::string&) {
          return absl::InvalidArgumentError(absl::StrCat("unknown option ", name));
        }};
  };
  if (absl::Status status = cmdline::ParseFlags(args, flags, rules, options.help); !status.ok()) {
    return status;
  }
  if (options.help) return options;
  if (options.meshes.empty()) {
    return absl::InvalidArgumentError("no mesh: give at least one --mesh or --generate");
  }
  if (options.write_meshes && options.out_dir.empty()) {
    return absl::InvalidArgumentError("--write-meshes needs --out DIR");
  }
  if (options.service && options.kernel_lanes != 0) {
    // The wire carries no width: a server's runs would not be the width the table names.
    return absl::InvalidArgumentError(
        "--kernel-lanes applies to in-process runs; a server runs its own widest width");
  }
  return options;
}

}  // namespace getme::bench
