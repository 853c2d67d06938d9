// Field and table files of a time folder: see FieldWriter.hpp.
#include "friction/output/FieldWriter.hpp"

#include <cmath>
#include <sstream>

#include "friction/core/AtomicFile.hpp"
#include "friction/dict/DictionaryWriter.hpp"

namespace friction {

void writeDisplacementField(const std::string& path, const std::vector<Vector2>& u, int precision) {
  DictionaryWriter w("pointVectorField", "D", "displacement [m] at the split-mesh points");
  w.setPrecision(precision);
  w.entryRaw("dimensions", "[0 1 0 0 0 0 0]");
  std::ostringstream s;
  s.precision(precision);
  s << "nonuniform List<vector>\n" << u.size() << "\n(\n";
  for (const Vector2& v : u) s << "(" << v.x() << " " << v.y() << " 0)\n";
  s << ")";
  w.entryRaw("internalField", s.str());
  w.beginDict("boundaryField");
  w.endDict();
  w.writeAtomic(path);
}

void writeFractureTable(const std::string& path, const std::vector<FractureRow>& rows,
                        const std::string& statusLine, int precision) {
  std::ostringstream out;
  out.precision(precision);
  out << "# s x y slip slipIncrement sigmaN tau ST residual state\n# " << statusLine << "\n";
  // One spelling of NaN ("nan", never "-nan"), which numpy, pandas and VTK read.
  const auto value = [&out](double v) -> std::ostream& {
    return std::isnan(v) ? out << "nan" : out << v;
  };
  for (const FractureRow& r : rows) {
    out << r.s << " " << r.x << " " << r.y << " " << r.slip << " " << r.slipIncrement << " ";
    value(r.sigmaN) << " ";
    value(r.tau) << " ";
    value(r.ST) << " ";
    value(r.residual) << " " << r.state << "\n";
  }
  writeTextAtomic(path, out.str());
}

}  // namespace friction
