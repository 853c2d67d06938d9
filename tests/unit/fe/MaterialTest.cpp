// Material (fe/Material.hpp) and the dimension: 'planeStress' has no meaning in 3D, and the
// case layer's read with the mesh's dimension refuses it there with the key's line.
#include <catch2/catch.hpp>
#include <string>

#include "friction/core/InputError.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/fe/Material.hpp"

using namespace friction;

namespace {

std::string inputErrorOf(const Dictionary& d, int dim) {
  try {
    Material::read(d, dim);
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("expected an InputError, none was thrown");
  return "";
}

}  // namespace

TEST_CASE("fe material refuses planeStress in 3D", "[fe][material]") {
  for (const char* value : {"yes", "no"}) {
    CAPTURE(value);
    const Dictionary d =
        Dictionary::parse(std::string("E 1e9;\nnu 0.25;\nplaneStress ") + value + ";\n", "mech");
    CHECK(inputErrorOf(d, 3) ==
          "mech:3: key 'planeStress' has no meaning in 3D (the mesh is 3D: every strain "
          "component is resolved, there is no plane); remove it");
    // The same dictionary is valid in 2D.
    CHECK(Material::read(d, 2).planeStress() == (std::string(value) == "yes"));
  }
  // Without the key a 3D material reads, and its laws are the 3D ones.
  const Material m = Material::read(Dictionary::parse("lambda 2;\nmu 1;\n", "mech"), 3);
  CHECK(!m.planeStress());
  CHECK(m.voigtMatrix3d()(0, 0) == 4.0);
  CHECK(m.voigtMatrix3d()(0, 1) == 2.0);
  CHECK(m.voigtMatrix3d()(3, 3) == 1.0);
}
