// libFuzzer target: readMesh on an arbitrary file, then splitFractures with each edge label
// as a fracture. The contract under test (MeshReader.hpp, SplitMesh.hpp): bad input ends in
// an InputError. Any other exception, a crash, a leak, UB or a hang is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "friction/fracture/SplitMesh.hpp"
#include "friction/mesh/MeshReader.hpp"

namespace {

// readMesh takes a path, so the input goes through a file; one per process (pid) so that
// parallel fuzzing jobs (-jobs=N) do not overwrite each other's input.
// libFuzzer ends with _Exit, so no destructor removes the file: run.sh points TMPDIR into
// the build tree instead.
const std::string& inputPath() {
  static const std::string path = (std::filesystem::temp_directory_path() /
                                   ("frictionFuzzMesh." + std::to_string(::getpid()) + ".msh"))
                                      .string();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream out(inputPath(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  friction::Mesh mesh;
  try {
    mesh = friction::readMesh(inputPath());
  } catch (const friction::InputError&) {
    return 0;
  }
  const std::set<int> labels(mesh.facetLabel.begin(), mesh.facetLabel.end());
  for (const int label : labels) {
    try {
      friction::splitFractures(mesh,
                               {{"fracture" + std::to_string(label), label, {"fuzz/meshDict", 1}}});
    } catch (const friction::InputError&) {
    }
  }
  // All labels at once: fractures that meet or cross are their own refusal path.
  if (labels.size() > 1) {
    std::vector<friction::FractureSpec> all;
    for (const int label : labels) all.push_back({"f" + std::to_string(label), label, {}});
    try {
      friction::splitFractures(mesh, all);
    } catch (const friction::InputError&) {
    }
  }
  return 0;
}
