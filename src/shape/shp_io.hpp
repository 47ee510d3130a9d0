#pragma once
// The Rockable shape library format (.shp): blocks "<" ... ">" of "key values" lines.
#include <iosfwd>
#include <string>
#include <vector>

#include "polydem/shape.hpp"

namespace polydem {

// Reads every "<" ... ">" block, as Rockable does (tokens outside blocks are skipped;
// '#', '/' and '!' start a comment to the end of the line). With "preCompDone y" and both
// `volume` and `I/m` given, the vertices are taken as they are (Rockable's convention: the
// principal frame about the centre of mass) and `position`/`orientation` (w x y z) give
// input_center/input_rotation; otherwise the mass properties are computed. Throws InputError
// "FILE:LINE: ..." (unknown key with the nearest valid one, bad number, missing '>').
std::vector<Shape> read_shp(std::istream& in, const std::string& file);
std::vector<Shape> read_shp_file(const std::string& path);

// Writes shapes with preCompDone y, full double precision, as Rockable's Shape::write does.
void write_shp(std::ostream& out, const std::vector<Shape>& shapes);
void write_shp_file(const std::string& path, const std::vector<Shape>& shapes);

}  // namespace polydem
