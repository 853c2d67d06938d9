// libFuzzer target: a whole case folder — dictionaries, boundary conditions, effects, mesh
// (and optionally a split mesh or restart time folders) — run in-process through what
// splitFractureNodes and frictionSolver do: read system/meshDict, read the mesh, name its
// patches, split, write and read back constant/splitMesh, build the FrictionCase, set up
// (assemble, factor) and run the time loop, writing time folders.
//
// The contract under test (README.md, exit codes): whatever the user writes ends in an
// InputError (exit 1), a factorisation status (exit 4) or a step status; the mains catch
// std::exception as a last resort, so an exception is not a finding here. A crash, an
// abort (a failed FRICTION_ASSERT: the fuzz build keeps assertions), an ASan/UBSan report,
// a leak or a hang is.
//
// Input format: files, each introduced by a line "==> <relative path>" and running to the
// next such line, e.g.
//   ==> system/controlDict
//   FoamFile { ... } endTime 1; deltaT 1; ...
//   ==> constant/mesh/square.msh
//   9 8 8 ...
// Paths are relative, of [A-Za-z0-9_.-/], without '..'. Bytes before the first header are
// ignored. If the input holds constant/splitMesh it is used as is (the split is skipped), so
// the split-mesh reader and restart folders are fuzzed too.
//
// Bounded work per input, so that executions stay fast: inputs over 64 kB, meshes over 3000
// points or 6000 triangles, more than 5 time steps, more than 200 optimizer iterations, and
// paths into /dev, /proc or /sys (a mesh or table named /dev/zero reads forever) are skipped.
#include <unistd.h>

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <string>

#include "friction/case/FrictionCase.hpp"
#include "friction/case/MeshSettings.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/fracture/SplitMeshIO.hpp"
#include "friction/mesh/MeshReader.hpp"

namespace fs = std::filesystem;
using namespace friction;

namespace {

constexpr std::size_t maxInputBytes = 64 * 1024;
constexpr std::size_t maxFiles = 24;
constexpr Index maxPoints = 3000, maxTriangles = 6000;
constexpr int maxSteps = 5;
constexpr long maxIterations = 200;

// One case folder per process (pid): parallel jobs (-jobs=N, -fork=N) do not share it.
// libFuzzer ends with _Exit, so run.sh points TMPDIR into the build tree.
const fs::path& caseDir() {
  static const fs::path dir =
      fs::temp_directory_path() / ("frictionFuzzCase." + std::to_string(::getpid()));
  return dir;
}

bool validPath(const std::string& p) {
  if (p.empty() || p.size() > 64 || p.front() == '/' || p.back() == '/') return false;
  for (const char c : p)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-' ||
          c == '/'))
      return false;
  for (const auto& part : fs::path(p))
    if (part == ".." || part == "." || part.empty()) return false;
  return true;
}

// The files of the input, or an empty map if it is not a case we run (see the header).
std::map<std::string, std::string> unpack(const std::string& text) {
  std::map<std::string, std::string> files;
  std::string* current = nullptr;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(pos, end - pos);
    if (line.rfind("==> ", 0) == 0) {
      const std::string path = line.substr(4);
      if (!validPath(path) || files.size() >= maxFiles) return {};
      current = &files[path];
      current->clear();  // a repeated header: the last one wins
    } else if (current) {
      *current += line;
      if (end < text.size()) *current += '\n';
    }
    pos = end + 1;
  }
  return files;
}

bool write(const std::map<std::string, std::string>& files) {
  std::error_code ec;
  fs::remove_all(caseDir(), ec);
  fs::create_directories(caseDir(), ec);
  if (ec) return false;
  for (const auto& [path, content] : files) {
    const fs::path p = caseDir() / path;
    fs::create_directories(p.parent_path(), ec);
    if (ec || fs::is_directory(p)) return false;  // "a" and "a/b" both given
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    if (!out) return false;
  }
  return true;
}

// Optimizer iterations asked for in system/frictionSolution (the default, 2000, if absent; 0
// if unreadable: FrictionCase then reports the problem itself).
long requestedIterations() {
  try {
    const Dictionary sol = Dictionary::read((caseDir() / "system" / "frictionSolution").string());
    const Dictionary* control = sol.findDict("control");
    const Dictionary* optimizer = control ? control->findDict("optimizer") : nullptr;
    if (!optimizer) return 0;
    return optimizer->found("maxIterations") ? optimizer->getInt("maxIterations") : 2000;
  } catch (const InputError&) {
  }
  return 0;
}

// What splitFractureNodes does, up to the file. False: the input is skipped (too large).
bool split(const std::string& dir) {
  const MeshSettings settings = MeshSettings::read(dir);
  // As the utility does: the record of what the split is made from (without it the solver
  // refuses the split mesh as stale), and the checks of hidden cuts and unlabelled edges.
  SplitMeshRecord madeFrom{settings.meshEntry, fileHash(settings.meshFile),
                           fileHash(settings.dictPath)};
  Mesh mesh = readMesh(settings.meshFile);
  if (mesh.numPoints() > maxPoints || mesh.numCells() > maxTriangles) return false;
  settings.nameLabels(mesh);
  const std::vector<FractureSpec> specs = settings.fractureSpecs(mesh);
  settings.checkMesh(mesh);
  SplitMesh s = splitFractures(mesh, specs);
  s.madeFrom = std::move(madeFrom);
  writeSplitMesh(s, (fs::path(dir) / "constant" / "splitMesh").string());
  return true;
}

// What frictionSolver does after its command line.
void solve(const std::string& dir) {
  std::ostream log(nullptr);  // discards (badbit: nothing is even formatted)
  FrictionCase c(dir);
  if (c.splitMesh().mesh.numPoints() > maxPoints || c.splitMesh().mesh.numCells() > maxTriangles ||
      c.time().numSteps() > maxSteps)
    return;
  if (c.setup(log) != FactorStatus::ok) return;
  c.run(log);
}

bool verbose() {
  static const bool v = std::getenv("FRICTION_FUZZ_VERBOSE") != nullptr;
  return v;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > maxInputBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const char* device : {"/dev", "/proc", "/sys"})
    if (text.find(device) != std::string::npos) return 0;
  const auto files = unpack(text);
  if (files.empty() || !write(files)) return 0;
  if (requestedIterations() > maxIterations) {
    if (verbose())
      std::fprintf(stderr, "fuzzCase: skipped (maxIterations over %ld)\n", maxIterations);
    return 0;
  }
  const std::string dir = caseDir().string();
  try {
    if (!files.count("constant/splitMesh") && !split(dir)) return 0;
    solve(dir);
  } catch (const std::exception& e) {
    // InputError, or the mains' last resort (message, exit code): not a finding of this
    // target. FRICTION_FUZZ_VERBOSE=1 prints what a main would, to follow one input.
    if (verbose()) std::fprintf(stderr, "fuzzCase: error: %s\n", e.what());
  }
  if (verbose()) std::fprintf(stderr, "fuzzCase: ran to the end\n");
  return 0;
}
