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
// input_center/input_rotation; otherwise the mass properties are computed. As Rockable, an
// unknown key is skipped with what follows it up to the next key, and an edge listed twice is
// merged: each gives a warning "FILE:LINE: key 'KEY': ..." appended to `warnings`, or printed
// on stderr when it is null. `isSurface` (a flag, or followed by 0/1) marks an open surface.
// Throws InputError "FILE:LINE: ..." (bad number, bad count, missing '>').
std::vector<Shape> read_shp(std::istream& in, const std::string& file, std::vector<std::string>* warnings = nullptr);
std::vector<Shape> read_shp_file(const std::string& path, std::vector<std::string>* warnings = nullptr);

// Writes shapes with preCompDone y, full double precision, as Rockable's Shape::write does.
void write_shp(std::ostream& out, const std::vector<Shape>& shapes);
void write_shp_file(const std::string& path, const std::vector<Shape>& shapes);

}  // namespace polydem
