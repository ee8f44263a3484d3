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

#include "read_text.hpp"
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
  bool crowded = false;  // on a 2 um patch, all arriving at once
};

// Each refusal exits 2 naming the file's line and key, and writes nothing.
TEST(Deposit, RefusesFilesItCannotPlaceOrDraw) {
  const BadFile bad[] = {
      // Three 4 um particles arriving at once on a 2 um patch fit its room but cannot lie apart;
      // ten do not fit at all (their spheres grown by half the clearance, 1.25 um, fill 1 393 um^3,
      // the patch and their heights grown by their largest radius 578 um^3).
      {"count: 3", "count: 3",
       "small.yaml:10:8: key 'patch': particle 2 of 3 found no place 2.5 um clear", true},
      {"count: 3", "count: 10", "small.yaml:4:10: key 'particles.count': 10 particles cannot fit",
       true},
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
    if (b.crowded) {
      text = replaced(text, "patch: {x: 6 um, y: 6 um}", "patch: {x: 2 um, y: 2 um}");
      text = replaced(text, "arrival_window: 10 ns", "arrival_window: 0 ns");
    }
    write(dir, "small.yaml", text);
    const auto r = run_coldspray("deposit small.yaml --out run --quiet", dir);
    EXPECT_EQ(r.status, 2) << b.to << "\n" << r.output;
    EXPECT_TRUE(has(r, b.message)) << b.to << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "run")) << b.to;
  }
}

// The thesis' ten-particle file (examples/deposit) with another count and patch.
std::string ten_particles(const std::string& count, const std::string& patch) {
  const std::string text =
      read_text(fs::path(COLDSPRAY_SOURCE_DIR) / "examples" / "deposit" / "ten-particles.yaml");
  return replaced(replaced(text, "count: 10\n", "count: " + count + "\n"),
                  "patch: {x: 30 um, y: 30 um}", "patch: " + patch);
}

// Issue 53: 100 000 particles on a 100 mm patch were placed one by one and their generated case
// read for 1 501 s before the point cap refused it, and 1 000 took 7.3 s. The deposit's points
// are now counted before any particle is placed (the substrate alone: 2.3e12 at 0.35 um), at
// the key that makes them: the patch here, the count when the particles have more.
TEST(Deposit, ADepositOverThePointCapIsRefusedBeforeItsParticlesArePlaced) {
  for (const std::string count : {"100000", "1000"}) {
    const fs::path dir = make_temp_dir("deposit");
    write(dir, "big.yaml", ten_particles(count, "{x: 100 mm, y: 100 mm}"));
    const auto r = run_coldspray("deposit big.yaml --write-case case.yaml", dir);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_TRUE(has(r, "key 'patch': the deposit would have about 2.3")) << r.output;
    EXPECT_TRUE(has(r, "(" + count + " particles about")) << r.output;
    EXPECT_TRUE(has(r, "more than limits.max_points, by default")) << r.output;
    EXPECT_FALSE(fs::exists(dir / "case.yaml"));
  }
  // A thousand 14 um particles at 0.35 um have 3.4e7 points, the substrate under a 300 um patch
  // 2.5e7; the cap is the --set one, as for the case.
  const fs::path dir = make_temp_dir("deposit");
  write(dir, "many.yaml", ten_particles("1000", "{x: 300 um, y: 300 um}"));
  const auto r =
      run_coldspray("deposit many.yaml --out run --quiet --set limits.max_points=1e6", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(has(r,
                  "key 'particles.count': the deposit would have about 5.86e+07 points (1000 "
                  "particles about 3.35e+07"))
      << r.output;
  EXPECT_TRUE(has(r, "more than limits.max_points = 1e+06")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "run"));
}

// 100 000 particles cannot lie apart over a 30 um patch and 50 ns of arrivals whatever the draws:
// refused at their count before placement, which used to search through every particle's 1 000
// draws until one found no place.
TEST(Deposit, ACountThatCannotFitThePatchIsRefusedBeforePlacement) {
  const fs::path dir = make_temp_dir("deposit");
  write(dir, "crowded.yaml", ten_particles("100000", "{x: 30 um, y: 30 um}"));
  const auto r = run_coldspray("deposit crowded.yaml --write-case case.yaml", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(has(r, "key 'particles.count': 100000 particles cannot fit")) << r.output;
  EXPECT_TRUE(has(r, "which holds about 53 of them")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "case.yaml"));
}

}  // namespace
}  // namespace coldspray::testing
