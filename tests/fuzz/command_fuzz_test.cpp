// A mutation fuzzer over the command line: real command lines of every subcommand, with options
// dropped, duplicated and swapped, hostile values (those of the --set fuzzer), unknown options,
// missing values, thread counts out of range and paths that are folders, missing, or devices,
// each run through the built binary under `timeout`. Every command is one that ends at once: a
// guard that no mutation touches stops it before it simulates (--write-case, --help, --steps 10,
// solver.end_time=1e-12 s), appended last, so that it wins over what the mutations put before it.
// It asserts what docs/reliability.md promises: the exit status is 0, 2 (bad input) or 3 (run
// fault), never 1 (internal error), a signal or the timeout, and a status-2 output starts with
// `error:` and names an option, a file or a key. The command lines in
// tests/data/fuzz/command-lines.txt (reproducers) run first.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "fuzz_support.hpp"
#include "run_command.hpp"

namespace coldspray::testing {
namespace {

const int kCommands = fuzz::budget(200, 60);
// `timeout`'s status when the time ran out. The longest command here takes well under a second
// in the release build; the limit only tells a stall from a slow machine. The release build's
// commands also get at most 4 GB of address space, so that one that grows without bound fails
// (std::bad_alloc, exit 1) instead of filling the machine's memory; ASan's shadow memory needs
// terabytes of address space, so not under the sanitizers.
constexpr int kTimedOut = 124;
const std::string kTimeout =
    std::string("timeout -k 5 60") + (fuzz::kSanitized ? "" : " prlimit --as=4000000000");

// A command line: `args`, which the mutations change, and `guard`, appended unchanged, which
// keeps it from simulating for long; `status`, the unmutated command's.
struct Base {
  std::vector<std::string> args;
  std::vector<std::string> guard;
  int status = 0;
};

const std::string kExamples = COLDSPRAY_SOURCE_DIR "/examples/";
const std::string kSmallDeposit = COLDSPRAY_TEST_DATA "/fuzz/deposit/small-deposit.yaml";
// A picosecond: the run sets up, takes a step or two and writes its outputs.
const std::string kQuickRun = "solver.end_time=1e-12 s";

std::vector<Base> bases() {
  const std::string hertz = kExamples + "verification/hertz.yaml";
  std::vector<Base> out{
      {{"check", kExamples + "al-14um-810.yaml"}, {}},
      {{"check", kExamples + "pd-vs-mpm/pd-cu-30um.yaml", "--set", "solver.cfl=0.4"}, {}},
      {{"check", hertz, "--set", "bodies.0.spacing=0.25 um"}, {}},
      {{"materials"}, {}},
      {{"materials", "al-ptw"}, {}},
      {{"impact", "--material", "al-ptw", "--diameter", "22um", "--velocity", "790m/s", "--threads",
        "1"},
       {"--quiet", "--write-case", "case.yaml"}},
      {{"impact", "--solver", "peridynamics", "--diameter", "30um", "--velocity", "500m/s",
        "--spacing", "1.5um", "--symmetry", "none", "--set", "solver.cfl=0.3"},
       {"--quiet", "--write-case", "case.yaml"}},
      {{"impact", "--material", "cu-jc", "--diameter", "14um", "--velocity", "810m/s", "--grid",
        "1um/0.35um", "--bonding", "energy", "--end-time", "20ns", "--coarsening", "1"},
       {"--quiet", "--write-case", "case.yaml"}},
      {{"deposit", kSmallDeposit, "--threads", "1"}, {"--quiet", "--write-case", "c.yaml"}},
      {{"material-test", "--material", "al-ptw", "--mode", "uniaxial-stress", "--strain-rate",
        "1e7 1/s", "--final-strain", "0.5", "--temperature", "400 K", "--out", "mt.csv"},
       {"--steps", "10"}},
      {{"run", hertz, "--threads", "1", "--out", "r"}, {"--quiet", "--set", kQuickRun}},
      {{"sweep", hertz, "--vary", "solver.cfl=0.3,0.4", "--out", "s", "--threads-per-job", "1"},
       {"--quiet", "--set", kQuickRun}},
      {{"pull-off", "r", "--speed", "10m/s", "--threads", "1"}, {"--quiet"}, 2}};  // no run r
  for (const char* sub : {"run", "impact", "check", "materials", "material-test", "bulk-fracture",
                          "pull-off", "sweep", "vcrit", "calibrate", "deposit"})
    out.push_back({{sub}, {"--help"}});
  return out;
}

// Values of options as a user or a probe might give them, beyond the --set fuzzer's.
constexpr std::array<std::string_view, 14> kCounts{
    "0", "-1",  "+2",  "99999", "2147483647", "2147483648", "1.5",
    "",  "two", "1e3", " 1",    "1 ",         "0x2",        "-0"};
constexpr std::array<std::string_view, 12> kPaths{".",
                                                  "missing.yaml",
                                                  "no/such/folder/x",
                                                  "/proc/x",
                                                  "/dev/full",
                                                  "/dev/null",
                                                  "/proc/self/mem",
                                                  "-",
                                                  "a\nb.yaml",
                                                  "",
                                                  "r/",
                                                  "case.yaml/x"};
constexpr std::array<std::string_view, 14> kOptions{
    "--frobnicate", "-x",    "--",          "-",       "---", "--=",    "--set",
    "--threads",    "--out", "--overwrite", "--quiet", "-h",  "--set=", "--threads="};
constexpr std::array<std::string_view, 8> kSetKeys{"solver.cfl",
                                                   "bodies.0.spacing",
                                                   "bodies.particle.velocity",
                                                   "grid.cell_size",
                                                   "output.snapshot_interval",
                                                   "materials.m",
                                                   "bodies.99.x",
                                                   "bodies.-1"};

bool is_path_option(const std::string& option) {
  return option == "--out" || option == "--write-case" || option == "--restart" ||
         option == "--initial-state";
}

class CommandMutator {
 public:
  explicit CommandMutator(std::uint64_t seed) : m_(seed) {}

  fuzz::Mutator& random() { return m_; }

  // One mutation of `a`, a[0] the subcommand, which stays.
  void mutate(std::vector<std::string>& a) {
    const bool one = a.size() == 1;  // the subcommand alone: only insertions
    const auto i = static_cast<long>(m_.below(a.size() - 1) + 1);
    switch (one ? 3 + m_.below(6) : m_.below(9)) {
      case 0:
        a.erase(a.begin() + i);
        break;
      case 1:
        a.insert(a.begin() + static_cast<long>(m_.below(a.size()) + 1), a[i]);
        break;
      case 2:
        std::swap(a[i], a[m_.below(a.size() - 1) + 1]);
        break;
      case 3:
        a.insert(a.begin() + i, std::string(m_.pick(kOptions)));
        break;
      case 4:
        a.insert(a.end(), {"--threads", std::string(m_.pick(kCounts))});
        break;
      case 5:
        a.insert(a.end(), {"--set", set_text()});
        break;
      case 6:
        hostile_path(a);
        break;
      default:
        hostile_value(a);
    }
  }

 private:
  std::string set_text() {
    std::string value(m_.hostile_value());
    // Long, though not 10^5 characters as the --set fuzzer's: the shell's `sh -c LINE` takes at
    // most 128 KiB in LINE (MAX_ARG_STRLEN), and three of them may be drawn.
    if (m_.below(8) == 0) value = std::string(30000, 'a');
    return std::string(m_.pick(kSetKeys)) + "=" + value;
  }

  // A path (an input file, a folder, an output) replaced by a missing one, a folder, a device.
  void hostile_path(std::vector<std::string>& a) {
    for (std::size_t n = a.size(), k = m_.below(n); n > 0; --n, k = (k + 1) % a.size()) {
      const bool path =
          k > 0 && (a[k].ends_with(".yaml") || a[k] == "r" || is_path_option(a[k - 1]));
      if (path) {
        a[k] = std::string(m_.pick(kPaths));
        return;
      }
    }
  }

  // An option's value replaced by a hostile one.
  void hostile_value(std::vector<std::string>& a) {
    for (std::size_t n = a.size(), k = m_.below(n); n > 0; --n, k = (k + 1) % a.size()) {
      if (k > 0 && a[k - 1].starts_with("--")) {
        a[k] = m_.below(2) == 0 ? std::string(m_.hostile_value()) : std::string(m_.pick(kCounts));
        return;
      }
    }
  }

  fuzz::Mutator m_;
};

// The shell's form of `text`: in single quotes, each single quote as '\''.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string command_line(const std::vector<std::string>& args) {
  std::string out;
  for (const std::string& a : args) {
    if (!out.empty()) out += ' ';
    out += quoted(a);
  }
  return out;
}

// Whether a refusal names what is wrong: an option or a value of the command line (`words`, the
// subcommand first; one of one character or none as ": X" or 'X'), a key, an option or argument
// that is missing (CLI11: "--set: 1 required TEXT missing", "case is required"), or an argument
// by its name in --help ("error: case: an empty path").
bool names_something(std::string output, const std::vector<std::string>& words) {
  // CLI11's last line, "Run with --help for more information.", names no culprit.
  output.erase(std::min(output.find("Run with --help"), output.size()));
  for (const char* named : {"key '", "--", " is required", "error: case:", "error: deposit:",
                            "error: IMPACT_DIR:", "error: file:"})
    if (output.find(named) != std::string::npos) return true;
  for (std::size_t i = 1; i < words.size(); ++i) {
    // A folder's trailing '/' is not in the message ("r/" is named "r").
    const std::string w =
        words[i].substr(0, std::min(words[i].find_last_not_of('/') + 1, std::size_t{200}));
    const bool found = w.size() >= 2 ? output.find(w) != std::string::npos
                                     : output.find(": " + w) != std::string::npos ||
                                           output.find("'" + w + "'") != std::string::npos;
    if (found) return true;
  }
  return false;
}

// The output without the case summary (`case 'NAME': ...` and its indented lines) that `run`,
// `impact` and `deposit` print before they create the run's folder, so that a folder they cannot
// create (`--out /proc/x`) is refused after it.
std::string after_case_summary(const std::string& output) {
  if (!output.starts_with("case '")) return output;
  std::size_t at = output.find('\n');
  while (at != std::string::npos && output.compare(at + 1, 2, "  ") == 0)
    at = output.find('\n', at + 1);
  return at == std::string::npos ? "" : output.substr(at + 1);
}

// Runs `coldspray ARGS` and checks its status and, if refused, its message.
void run_args(const std::vector<std::string>& args, const std::string& label) {
  const std::string line = command_line(args);
  const auto start = std::chrono::steady_clock::now();
  const CommandResult r = run_coldspray_under(kTimeout, line);
  const std::string shown = label + ": coldspray " + line.substr(0, 2000) + "\n(" +
                            std::to_string(fuzz::seconds_since(start)) + " s)\n" +
                            r.output.substr(0, 2000);
  EXPECT_NE(r.status, kTimedOut) << "timed out: " << shown;
  EXPECT_TRUE(r.status == 0 || r.status == 2 || r.status == 3)
      << "status " << r.status << ": " << shown;
  if (r.status == 2) {
    EXPECT_TRUE(after_case_summary(r.output).starts_with("error:")) << shown;
    EXPECT_TRUE(names_something(r.output, args)) << shown;
  }
}

// `text` with @SOURCE@ and @DATA@ replaced by the source tree and tests/data.
std::string with_folders(std::string text) {
  for (const auto& [name, value] :
       {std::pair<std::string, std::string>{"@SOURCE@", COLDSPRAY_SOURCE_DIR},
        {"@DATA@", COLDSPRAY_TEST_DATA}})
    for (std::size_t at; (at = text.find(name)) != std::string::npos;)
      text.replace(at, name.size(), value);
  return text;
}

// tests/data/fuzz/command-lines.txt: lines "STATUS COMMAND [==> START]"; each command exits
// with STATUS and its output begins with START.
TEST(CommandFuzz, Reproducers) {
  std::ifstream in(COLDSPRAY_TEST_DATA "/fuzz/command-lines.txt");
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line.starts_with("#")) continue;
    const std::size_t arrow = line.find(" ==> ");
    const std::string start =
        arrow == std::string::npos ? "" : with_folders(line.substr(arrow + 5));
    std::istringstream fields(with_folders(line.substr(0, arrow)));
    int status = -1;
    fields >> status;
    std::string command;
    std::getline(fields >> std::ws, command);
    const CommandResult r = run_coldspray_under(kTimeout, command);
    EXPECT_EQ(r.status, status) << command << "\n" << r.output;
    EXPECT_TRUE(r.output.starts_with(start)) << command << "\n" << r.output;
    ++n;
  }
  EXPECT_GE(n, 20);
}

TEST(CommandFuzz, NoInternalErrorNoSignalNoStall) {
  const std::vector<Base> commands = bases();
  for (const Base& b : commands) {  // unmutated first
    std::vector<std::string> args = b.args;
    args.insert(args.end(), b.guard.begin(), b.guard.end());
    const CommandResult r = run_coldspray_under(kTimeout, command_line(args));
    EXPECT_EQ(r.status, b.status) << command_line(args) << "\n" << r.output;
  }
  CommandMutator m(20261206);
  for (int i = 0; i < kCommands; ++i) {
    const Base& b = m.random().pick(commands);
    std::vector<std::string> args = b.args;
    for (std::size_t k = m.random().below(3) + 1; k > 0; --k) m.mutate(args);
    args.insert(args.end(), b.guard.begin(), b.guard.end());
    run_args(args, "command " + std::to_string(i));
  }
}

}  // namespace
}  // namespace coldspray::testing
