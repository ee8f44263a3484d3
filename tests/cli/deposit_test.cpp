// `coldspray deposit` (docs/deposit.md): a small deposit run end to end, its report against its
// own summary, the generated case reproducible from the seed, and the deposit files it refuses.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "run_command.hpp"
#include "temp_dir.hpp"

namespace coldspray::testing {
namespace {

namespace fs = std::filesystem;

// Three particles of about 4 um (normal sizes) at 900 m/s over a 6 um patch, 1/0.5 um: about
// 6 700 points, 8 s on one thread.
const std::string kSmall = R"(name: small-deposit
seed: 3
particles:
  count: 3
  material: al-ptw
  diameter: {distribution: normal, mean: 4 um, deviation: 0.3 um}
  velocity: 900 m/s
substrate:
  thickness: 3 um
patch: {x: 6 um, y: 6 um}
arrival_window: 10 ns
settle_time: 20 ns
grid: 1um/0.5um
)";

std::string write(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// With an easy bond (G_c = 20 J/m^2, as the bonding-impact verification case) all three stick:
// the report's rows are the summary's bodies, its deposition efficiency their masses' share.
TEST(Deposit, ReportsEachParticleAndTheDeposit) {
  const fs::path dir = make_temp_dir("deposit");
  const std::string file = write(dir, "small.yaml", kSmall);
  const auto r = run_coldspray(
      "deposit small.yaml --out run --threads 1 --quiet --set bonding.critical_energy=20",
      dir.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(has(r, "particle  d (um)")) << r.output;
  EXPECT_TRUE(has(r, "tools/coldspray_plot.py deposit")) << r.output;
  const nlohmann::json d = nlohmann::json::parse(read_text(dir / "run" / "deposit.json"));
  const nlohmann::json s = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  ASSERT_EQ(d["particles"].size(), 3u);
  double sprayed = 0.0, bonded = 0.0;
  int bonded_count = 0;
  for (const auto& p : d["particles"]) {
    const auto& body = s["bodies"][p["name"].get<std::string>()];
    EXPECT_EQ(p["verdict"], body["verdict"]["outcome"]) << p["name"];
    EXPECT_EQ(p["flattening_ratio"], body["flattening_ratio"]);
    EXPECT_EQ(p["bonded_area"], body["bonded_area"]);
    const double area_by_partner =
        p["bonded_area_to_particles"].get<double>() + p["bonded_area_to_substrate"].get<double>();
    EXPECT_NEAR(area_by_partner, body["bonded_area"].get<double>(), 1e-9 * 1e-12);
    const double mass = body["mass"].get<double>() + body["departed"]["mass"].get<double>();
    EXPECT_DOUBLE_EQ(p["sprayed_mass"].get<double>(), mass);
    sprayed += mass;
    if (p["verdict"] == "bonded") {
      bonded += mass;
      ++bonded_count;
    }
  }
  EXPECT_GE(bonded_count, 1) << r.output;
  EXPECT_DOUBLE_EQ(d["deposition_efficiency"].get<double>(), bonded / sprayed);
  EXPECT_GT(d["coverage"].get<double>(), 0.0);
  EXPECT_GT(d["mean_thickness"].get<double>(), 0.0);
  EXPECT_LE(d["mean_thickness"].get<double>(), d["max_thickness"].get<double>());
  EXPECT_GE(d["porosity"].get<double>(), 0.0);
  EXPECT_LT(d["porosity"].get<double>(), 1.0);
  // The voxel is the spacing: a 6 um patch is 12 x 12 columns.
  EXPECT_EQ(d["thickness_map"]["values"].size(), 144u);

  // --restart continues the run from its last checkpoint (here its end) and reports it again;
  // a file that places other particles is refused.
  const std::string first = read_text(dir / "run" / "deposit.json");
  const auto again = run_coldspray("deposit small.yaml --restart run --threads 1 --quiet", dir);
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_EQ(read_text(dir / "run" / "deposit.json"), first);
  write(dir, "other.yaml", replaced(kSmall, "seed: 3", "seed: 4"));
  const auto other = run_coldspray("deposit other.yaml --restart run --quiet", dir);
  EXPECT_EQ(other.status, 2) << other.output;
  EXPECT_TRUE(has(other, "--restart: the run's bodies are not the particles other.yaml places"))
      << other.output;
}

// The same file writes the same case; another seed places the particles elsewhere.
// An interrupted deposit names the command that continues it, `deposit FILE --restart RUN`,
// which finishes the run and writes deposit.json (`run --restart` would not).
TEST(Deposit, AnInterruptedDepositSaysHowToContinueIt) {
  const fs::path dir = make_temp_dir("deposit");
  const std::string file = write(dir, "small.yaml", kSmall);
  const fs::path run = dir / "run", log = dir / "log.txt";
  const pid_t pid = spawn_coldspray({"deposit", file, "--out", run.string(), "--threads", "1",
                                     "--quiet", "--set", "output.checkpoint_interval=2ns"},
                                    log.string());
  bool checkpointed = false;
  for (int k = 0; k < 60000 && !checkpointed; ++k) {
    std::error_code ec;
    checkpointed = !fs::is_empty(run / "checkpoints", ec) && !ec;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  kill(pid, SIGINT);
  EXPECT_EQ(exit_status(pid), 130);
  ASSERT_TRUE(checkpointed);
  const std::string said = read_text(log);
  const std::string command = "coldspray deposit " + file + " --restart " + run.string();
  EXPECT_TRUE(said.find("continue with: " + command) != std::string::npos) << said;
  EXPECT_FALSE(fs::exists(run / "deposit.json"));
  const auto again = run_coldspray(command.substr(command.find(' ') + 1) + " --quiet");
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_TRUE(fs::exists(run / "deposit.json"));
}

TEST(Deposit, TheSeedFixesTheCase) {
  const fs::path dir = make_temp_dir("deposit");
  write(dir, "small.yaml", kSmall);
  write(dir, "other.yaml", replaced(kSmall, "seed: 3", "seed: 4"));
  for (const char* out : {"a.yaml", "b.yaml"}) {
    const auto r = run_coldspray(std::string("deposit small.yaml --write-case ") + out, dir);
    ASSERT_EQ(r.status, 0) << r.output;
  }
  ASSERT_EQ(run_coldspray("deposit other.yaml --write-case c.yaml", dir).status, 0);
  const std::string a = read_text(dir / "a.yaml");
  EXPECT_EQ(a, read_text(dir / "b.yaml"));
  EXPECT_NE(a, replaced(read_text(dir / "c.yaml"), "other.yaml", "small.yaml"));
  EXPECT_TRUE(has({0, a}, "name: p3")) << a;
  EXPECT_TRUE(has({0, a}, "name: substrate")) << a;
  // By default the substrate's normal at particle-substrate pairs and the average gradient
  // between particles; contact_normal names another rule for all pairs.
  EXPECT_TRUE(has({0, a}, "normal: body:substrate")) << a;
  EXPECT_TRUE(has({0, a}, "other_pairs_normal: average-gradient")) << a;
  write(dir, "highest.yaml", kSmall + "contact_normal: highest-id\n");
  ASSERT_EQ(run_coldspray("deposit highest.yaml --write-case h.yaml", dir).status, 0);
  const std::string h = read_text(dir / "h.yaml");
  EXPECT_TRUE(has({0, h}, "normal: highest-id")) << h;
  EXPECT_FALSE(has({0, h}, "other_pairs_normal")) << h;
  // The generated cases run as case files.
  EXPECT_EQ(run_coldspray("check a.yaml", dir).status, 0);
  EXPECT_EQ(run_coldspray("check h.yaml", dir).status, 0);
}

struct BadFile {
  std::string from, to, message;
};

// Each refusal exits 2 naming the file's line and key, and writes nothing.
TEST(Deposit, RefusesFilesItCannotPlaceOrDraw) {
  const BadFile bad[] = {
      // Ten 4 um particles arriving at once on a 2 um patch cannot lie apart.
      {"count: 3", "count: 10",
       "small.yaml:10:8: key 'patch': particle 2 of 10 found no place 2.5 um clear"},
      {"deviation: 0.3 um", "deviation: 1.5 um",
       "key 'particles.diameter.deviation': reaches sizes <= 0 within 3 deviations"},
      {"{distribution: normal, mean: 4 um, deviation: 0.3 um}",
       "{distribution: log-normal, median: 4 um, spread: 0.8}", "key 'particles.diameter.spread'"},
      {"{distribution: normal, mean: 4 um, deviation: 0.3 um}",
       "{distribution: fixed, size: -4 um}", "key 'particles.diameter.size'"},
      {"{distribution: normal, mean: 4 um, deviation: 0.3 um}",
       "{distribution: uniform, size: 4 um}", "key 'particles.diameter.distribution'"},
      {"count: 3", "count: 0", "key 'particles.count'"},
      {"seed: 3", "seed: 3\nsed: 4", "small.yaml:3:1: key 'sed': unknown key 'sed'"},
      {"grid: 1um/0.5um", "grid: 3um/0.5um", "the cell (3 um) must be at most half"},
  };
  for (const BadFile& b : bad) {
    const fs::path dir = make_temp_dir("deposit");
    std::string text = replaced(kSmall, b.from, b.to);
    if (b.from == "count: 3")
      text = replaced(text, "patch: {x: 6 um, y: 6 um}", "patch: {x: 2 um, y: 2 um}");
    if (b.to == "count: 10") text = replaced(text, "arrival_window: 10 ns", "arrival_window: 0 ns");
    write(dir, "small.yaml", text);
    const auto r = run_coldspray("deposit small.yaml --out run --quiet", dir);
    EXPECT_EQ(r.status, 2) << b.to << "\n" << r.output;
    EXPECT_TRUE(has(r, b.message)) << b.to << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "run")) << b.to;
  }
}

}  // namespace
}  // namespace coldspray::testing
