#include "run/checkpoints.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <vector>

#include "case/load.hpp"
#include "checkpoint/archive.hpp"
#include "checkpoint/fields.hpp"
#include "core/error.hpp"
#include "io/hdf5_file.hpp"
#include "mpm/departures.hpp"
#include "run/run_folder.hpp"

namespace coldspray::run {

namespace fs = std::filesystem;

namespace {

// Everything a checkpoint holds, in either direction.
template <class Archive, class State>
void all_fields(Archive& a, State& s, Recorder& rec, StepRule& rule) {
  checkpoint::fields(a, s);
  rec.fields(a);
  a("rule/end", rule.end);
  a("rule/extensions_left", rule.extensions_left);
}

// What a restarted MPM run must size to the checkpoint's points: the step's scratch arrays
// (points leave the MPM's grid, mpm/departures.hpp). Peridynamics keeps its points.
void fit_to_points(mpm::State& s) { mpm::fit_scratch_to_points(s); }
void fit_to_points(pd::State&) {}

// InputError unless the checkpoint is of `method`'s solver.
void expect_solver(checkpoint::CheckpointReader& reader, const fs::path& path,
                   const std::string& method) {
  std::string saved;
  reader("solver", saved);
  if (saved != method)
    throw InputError(path.string(), "solver",
                     fmt::format("is a {} checkpoint, not {}", saved, method));
}

// InputError unless the checkpoint is one of the run in `rec`'s folder: its run id that of the
// folder's run_id.txt and its case that of the folder's case.resolved.yaml.
void expect_own_run(checkpoint::CheckpointReader& reader, const fs::path& path,
                    const Recorder& rec) {
  std::string id, text;
  reader("run_id", id);
  if (id != rec.run_id())
    throw InputError(path.string(), "run_id",
                     fmt::format("is run {}'s checkpoint, not that of the run in '{}' ({}): a "
                                 "folder continues only from its own checkpoints",
                                 id, rec.folder().string(), rec.run_id()));
  reader("case", text);
  std::ifstream in(rec.folder() / "case.resolved.yaml", std::ios::binary);
  const std::string folder_case{std::istreambuf_iterator<char>(in),
                                std::istreambuf_iterator<char>()};
  if (text != folder_case)
    throw InputError(path.string(), "case",
                     fmt::format("differs from '{}': the folder's run is another case",
                                 (rec.folder() / "case.resolved.yaml").string()));
}

}  // namespace

template <class State>
fs::path write_checkpoint(State& s, Recorder& rec, StepRule& rule) {
  const fs::path folder = rec.folder() / "checkpoints";
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw RunFault(fmt::format("cannot create '{}': {}", folder.string(), ec.message()));
  const fs::path path = folder / fmt::format("step_{:08d}.h5", s.step);
  {
    io::Hdf5File file(path, io::Hdf5File::Mode::Create);
    checkpoint::CheckpointWriter writer(file);
    int format = kCheckpointFormat;
    std::string method = s.discretisation.method, text = rec.resolved_case(), id = rec.run_id();
    writer("format", format);
    writer("solver", method);
    writer("case", text);
    writer("run_id", id);
    all_fields(writer, s, rec, rule);
    file.save();
  }
  const std::vector<fs::path> kept = step_files(folder, ".h5");
  const auto keep = static_cast<std::size_t>(rec.checkpoints().keep());
  for (std::size_t k = 0; k + keep < kept.size(); ++k) fs::remove(kept[k], ec);
  return path;
}

fs::path find_checkpoint(const fs::path& file_or_run) {
  if (fs::is_regular_file(file_or_run)) return file_or_run;
  const std::vector<fs::path> files = step_files(file_or_run / "checkpoints", ".h5");
  if (files.empty())
    throw InputError(file_or_run.string(), "",
                     "holds no checkpoint (checkpoints/step_*.h5): not a run folder, or a run "
                     "that wrote none");
  return files.back();
}

case_file::Case checkpoint_case(const fs::path& path) {
  const io::Hdf5File file(path, io::Hdf5File::Mode::Read);
  checkpoint::CheckpointReader reader(file);
  int format = 0;
  reader("format", format);
  if (format != kCheckpointFormat)
    throw InputError(path.string(), "format",
                     fmt::format("is checkpoint format {}; this coldspray reads format {}", format,
                                 kCheckpointFormat));
  std::string text;
  reader("case", text);
  return case_file::load_case_text(path.string(), text);
}

template <class State>
void read_checkpoint(const fs::path& path, State& s, Recorder& rec, StepRule& rule) {
  const io::Hdf5File file(path, io::Hdf5File::Mode::Read);
  checkpoint::CheckpointReader reader(file);
  expect_solver(reader, path, s.discretisation.method);
  expect_own_run(reader, path, rec);
  all_fields(reader, s, rec, rule);
  fit_to_points(s);
  rec.resume();  // the folder cut back to the checkpoint, once all of it was read
}

template <class State>
void load_initial_state(const fs::path& path, State& s) {
  const case_file::Case saved = checkpoint_case(path);
  const io::Hdf5File file(path, io::Hdf5File::Mode::Read);
  checkpoint::CheckpointReader reader(file);
  expect_solver(reader, path, s.discretisation.method);
  bool compatible = saved.bodies.size() == s.bodies.size();
  for (std::size_t b = 0; compatible && b < s.bodies.size(); ++b) {
    // Its points at the checkpoint and those that had left the MPM's grid by then
    // (mpm/departures.hpp): as many as this case seeds.
    const std::string at = "bodies/" + std::to_string(b) + "/";
    std::size_t begin = 0, end = 0, departed = 0;
    reader(at + "begin", begin), reader(at + "end", end), reader(at + "departed/points", departed);
    compatible = saved.bodies[b].name == s.bodies[b].name &&
                 end - begin + departed == s.bodies[b].end - s.bodies[b].begin;
  }
  if (!compatible)
    throw InputError(path.string(), "bodies",
                     "holds other bodies than this case seeds (their names, order and points, "
                     "from shape and spacing, must be the checkpoint's)");
  checkpoint::fields(reader, s);
  fit_to_points(s);
  s.time = 0.0;
  s.step = 0;
}

template fs::path write_checkpoint(mpm::State&, Recorder&, StepRule&);
template fs::path write_checkpoint(pd::State&, Recorder&, StepRule&);
template void read_checkpoint(const fs::path&, mpm::State&, Recorder&, StepRule&);
template void read_checkpoint(const fs::path&, pd::State&, Recorder&, StepRule&);
template void load_initial_state(const fs::path&, mpm::State&);
template void load_initial_state(const fs::path&, pd::State&);

}  // namespace coldspray::run
