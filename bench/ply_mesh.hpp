// The full Stanford dragon ships only as a gzip'd ASCII PLY; the bench converts it
// once into an OBJ that facet's scene loader reads.
#pragma once

#include <string>

namespace facet {

// Converts `ply_gz` (ASCII PLY, gzip'd: vertices x y z first, faces as index lists)
// into the OBJ `obj_out`, unless that file exists already. Returns false with a reason
// in *why when zlib is missing or the file cannot be read.
bool ply_gz_to_obj(const std::string& ply_gz, const std::string& obj_out, std::string* why);

}  // namespace facet
