// A fuzzer over `--set KEY=VALUE` as a user types it: the text is split by parse_override and
// applied to an example case by load_case_text, as `coldspray check CASE --set TEXT` does. The
// texts are hostile: no '=', '=' only, empty keys, list indices out of range, keys and values of
// 10^5 characters, NUL, control characters and invalid UTF-8, flow nesting 10^4 deep, anchors and
// aliases, numbers and units at the edge of their syntax. It asserts what docs/reliability.md
// promises: no crash, no input slower than kPerInputSeconds, and every refusal an InputError
// with a message, located at `--set` (with the key once there is one) or at the key of the file
// that the --set value contradicts. The reproducers in tests/data/fuzz/set (one --set text a
// file) run first.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <array>
#include <chrono>
#include <string>
#include <string_view>
#include <vector>

#include "case/load.hpp"
#include "core/error.hpp"
#include "fuzz_support.hpp"
#include "read_text.hpp"

namespace coldspray::case_file {
namespace {

namespace fs = std::filesystem;
using coldspray::testing::read_text;

const int kSetInputs = fuzz::budget(3000, 1000);
constexpr const char* kSetCaseName = "fuzzed.yaml";

// Valid cases, each a different part of the schema: MPM 3D and r-z, peridynamics, several
// bodies, materials of the case's own, bonding, heat.
constexpr std::array<std::string_view, 6> kCases{"al-14um-810.yaml",
                                                 "coldspray/al-14um-810-rz.yaml",
                                                 "pd-vs-mpm/pd-cu-30um.yaml",
                                                 "verification/hertz.yaml",
                                                 "verification/bonding-impact.yaml",
                                                 "verification/heat-conduction.yaml"};

constexpr std::array<std::string_view, 38> kHostileKeys{"",
                                                        ".",
                                                        "..",
                                                        "a..b",
                                                        ".solver",
                                                        "solver.",
                                                        "bodies.99",
                                                        "bodies.99.x",
                                                        "bodies.-1",
                                                        "bodies.-1.x",
                                                        "bodies.+0",
                                                        "bodies.00",
                                                        "bodies. 0",
                                                        "bodies.1e0",
                                                        "bodies.0x0",
                                                        "bodies.4294967296",
                                                        "bodies.18446744073709551616.x",
                                                        "bodies.0.shape.radius.x",
                                                        "solver.cfl.x",
                                                        "solver",
                                                        "bodies",
                                                        "materials",
                                                        "limits",
                                                        "output",
                                                        "grid",
                                                        "metrics",
                                                        "so\x01lver.cfl",
                                                        "solver\t.cfl",
                                                        "\xff\xfe",
                                                        "solver.\xc3(",
                                                        "name",
                                                        "name.x",
                                                        "bodies.particle.velocity.0",
                                                        "bodies.particle.velocity.3",
                                                        "materials.m.base",
                                                        "~",
                                                        "[a]",
                                                        "{a: 1}"};

// Values and keys that are long or deep: built once.
std::vector<std::string> big_values() {
  const std::size_t n = 100000;
  return {std::string(10000, '[') + "1" + std::string(10000, ']'),
          [] {
            std::string s;
            for (int i = 0; i < 10000; ++i) s += "{a: ";
            return s + "1" + std::string(10000, '}');
          }(),
          std::string(10000, '['),
          std::string(n, '1'),
          "1." + std::string(n, '0') + "1 um",
          std::string(n, 'a'),
          std::string(n, ' ') + "1",
          "7 " + std::string(n, 'm'),
          [n] {
            std::string s = "[";
            while (s.size() < n) s += "1 um, ";
            return s + "1 um]";
          }(),
          [] {
            std::string s = "1 m";
            for (int i = 0; i < 5000; ++i) s += "*m/m";
            return s;
          }(),
          std::string("1\0 um", 5)};
}

std::vector<std::string> big_keys() {
  std::string dotted = "a";
  for (int i = 0; i < 10000; ++i) dotted += ".a";
  return {std::string(100000, 'k'), dotted, "solver." + std::string(100000, 'c'),
          std::string("solver\0.cfl", 11), std::string(10000, '.')};
}

// Every key path of the tree (list items by index and by name), as --set writes them.
void collect_paths(const YAML::Node& node, const std::string& path, std::vector<std::string>& out) {
  if (!path.empty()) out.push_back(path);
  const std::string prefix = path.empty() ? "" : path + ".";
  if (node.IsMap()) {
    for (const auto& entry : node)
      collect_paths(entry.second, prefix + entry.first.as<std::string>(), out);
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      collect_paths(node[i], prefix + std::to_string(i), out);
      if (node[i].IsMap() && node[i]["name"] && node[i]["name"].IsScalar())
        out.push_back(prefix + node[i]["name"].as<std::string>());
    }
  }
}

struct Seed {
  std::string text;
  std::vector<std::string> paths;
};

std::vector<Seed> set_seeds() {
  std::vector<Seed> out;
  for (std::string_view c : kCases) {
    Seed s{read_text(fs::path(COLDSPRAY_SOURCE_DIR "/examples") / c), {}};
    collect_paths(YAML::Load(s.text), "", s.paths);
    out.push_back(std::move(s));
  }
  return out;
}

class SetTexts {
 public:
  explicit SetTexts(fuzz::Mutator& m) : m_(m), big_values_(big_values()), big_keys_(big_keys()) {}

  // One --set text for a case with key paths `paths`.
  std::string next(const std::vector<std::string>& paths) {
    const std::string k = key(paths), v = value();
    switch (m_.below(12)) {
      case 0:
        return k;
      case 1:
        return "=" + v;
      case 2:
        return k + "=";
      case 3:
        return " " + k + " = " + v + " ";
      case 4:
        return k + "==" + v;
      case 5:
        return "=";
      default:
        return k + "=" + v;
    }
  }

 private:
  std::string key(const std::vector<std::string>& paths) {
    switch (m_.below(6)) {
      case 0:
        return std::string(m_.pick(kHostileKeys));
      case 1:
        return m_.pick(big_keys_);
      case 2: {  // a real key with a part mangled
        std::string k = m_.pick(paths);
        m_.mutate(k);
        return k;
      }
      case 3:
        return m_.pick(paths) + "." + std::string(m_.pick(kHostileKeys));
      default:
        return m_.pick(paths);
    }
  }

  std::string value() {
    switch (m_.below(5)) {
      case 0:
        return m_.pick(big_values_);
      case 1: {  // a hostile value, mutated
        std::string v(m_.hostile_value());
        m_.mutate(v);
        return v;
      }
      default:
        return std::string(m_.hostile_value());
    }
  }

  fuzz::Mutator& m_;
  std::vector<std::string> big_values_, big_keys_;
};

// Applies the --set texts to the case as `coldspray check` would and checks the refusal, if any;
// whether the case was refused.
bool check_sets(const Seed& seed, const std::vector<std::string>& texts, const std::string& label) {
  const auto start = std::chrono::steady_clock::now();
  bool refused = true;
  std::string shown;
  for (const std::string& t : texts) shown += " --set '" + t.substr(0, 200) + "'";
  try {
    std::vector<Override> sets;
    for (const std::string& t : texts) sets.push_back(parse_override(t));
    load_case_text(kSetCaseName, seed.text, {}, sets);
    refused = false;
  } catch (const InputError& e) {
    // At the --set, or at the key of the file that a --set value contradicts (contact.mpm.normal
    // naming a body a --set renamed; the grid's cell size, where its size cap is reported).
    const bool at_a_key = e.where().starts_with(kSetCaseName) && !e.key().empty();
    EXPECT_TRUE(e.where().starts_with("--set") || at_a_key) << label << shown << ": " << e.what();
    EXPECT_FALSE(e.message().empty()) << label << shown;
  } catch (const std::exception& e) {
    ADD_FAILURE() << label << shown << ": not an InputError: " << e.what();
  }
  EXPECT_LT(fuzz::seconds_since(start), fuzz::kPerInputSeconds) << label << shown;
  return refused;
}

// Each reproducer is refused by some of the cases (a velocity along x only in r-z), every time
// at its --set.
TEST(SetFuzz, ReproducersAreRefusedAtTheirSet) {
  const std::vector<Seed> cases = set_seeds();
  for (const auto& entry : fs::directory_iterator(COLDSPRAY_TEST_DATA "/fuzz/set")) {
    int refused = 0;
    for (const Seed& seed : cases)
      refused += check_sets(seed, {read_text(entry.path())}, entry.path().filename().string());
    EXPECT_GT(refused, 0) << entry.path();
  }
}

TEST(SetFuzz, NoCrashNoStallEveryErrorAtItsSet) {
  const std::vector<Seed> cases = set_seeds();
  fuzz::Mutator m(20261204);
  SetTexts texts(m);
  int accepted = 0;
  for (int i = 0; i < kSetInputs; ++i) {
    const Seed& seed = m.pick(cases);
    std::vector<std::string> sets;
    for (std::size_t n = m.below(3) + 1; n > 0; --n) sets.push_back(texts.next(seed.paths));
    accepted += !check_sets(seed, sets, "input " + std::to_string(i));
  }
  // Not all refused: the harness itself does not break every case (of the 3000, 18 load; of the
  // first 300, none, hence the sanitizers' 1000).
  EXPECT_GT(accepted, 0);
}

}  // namespace
}  // namespace coldspray::case_file
