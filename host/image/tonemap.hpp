// Tone mapping of linear radiance for the 8-bit PNG beside the EXR: the display-encoded
// value (what an sRGB display takes) of one linear channel, after the exposure.
//   clip    the linear value clamped to [0, 1], sRGB-encoded (IEC 61966-2-1): exact below
//           1, flat white above (highlights lose their detail).
//   filmic  a sigmoid in log2 exposure (the shape of AgX and Blender's Filmic): mid grey
//           0.18 maps to 0.461 with the same contrast as the clip (0.149 display units a
//           stop), shadows roll off toward 0 and highlights toward 1 over about 7 stops
//           above mid grey instead of clipping 2.5 stops above it. Applied per channel,
//           so saturated highlights run to white as film does.
#pragma once

#include <optional>
#include <string_view>

namespace facet {

enum class ToneMap { Clip, Filmic };

// The display-encoded value in [0, 1] of `linear` (already scaled by the exposure);
// NaN and negative values give 0.
float tonemap_display(ToneMap map, float linear);

// "clip" / "filmic".
const char* tonemap_name(ToneMap map);
std::optional<ToneMap> tonemap_from_name(std::string_view name);

}  // namespace facet
