// IES LM-63 photometric files (LM-63-1986, -1991, -1995 and -2002) -> their candela table.
//
// readIesFile() reads the header line ("IESNA:LM-63-1995", "IESNA:LM-63-2002", "IESNA91", or
// none for LM-63-1986), skips the keyword lines up to TILT=, and reads the numbers that follow
// (separated by blanks, commas or line ends, as the standard allows): lamp count, lumens per
// lamp, candela multiplier, vertical and horizontal angle counts, photometric type, units, the
// luminous opening's width, length and height, ballast factor, ballast-lamp photometric factor
// ("future use" in 1995 and 2002), input watts, the vertical angles, the horizontal angles, and
// one candela value per (horizontal, vertical) pair, horizontal angle by horizontal angle.
//
// - TILT=NONE: no tilt data. TILT=INCLUDE: the lamp-to-luminaire geometry, the tilt angle count
//   and that many angles and factors are read and checked, then not applied (they describe how
//   output changes when a lamp is tilted from the measured position, which a render never does).
//   TILT=<file> (tilt data in another file) is refused.
// - Candela values are multiplied by the candela multiplier (and nothing else: the ballast
//   factors are read, not applied, as Cycles, RenderMan and hdEmbree read them).
// - Photometric type C (1) only, the type of nearly every architectural file: types A (3,
//   automotive) and B (2, floodlights) are refused with the type named.
// - Type C horizontal angles must be one of the symmetries LM-63 lists: a single 0 (symmetric
//   about the vertical axis), 0..90 (symmetric in each quadrant), 0..180 (symmetric about the
//   0-180 plane), 90..270 (symmetric about the 90-270 plane), 0..360. Vertical angles must run
//   0..90, 90..180 or 0..180. Both lists must increase.
// A file that breaks a rule raises IesFileError naming file:line and what was expected.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace fluence::texture {

class IesFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The candela table as the file gives it (its symmetry not yet unfolded: render/ies_profile.h).
struct IesTable {
    std::string standard;                  // the header line, "" for LM-63-1986
    std::vector<float> verticalDegrees;    // increasing: 0 (nadir) .. 180 (zenith)
    std::vector<float> horizontalDegrees;  // increasing
    std::vector<float> candela;            // horizontal-major: candela[h * vertical count + v], multiplied
    float at(std::size_t h, std::size_t v) const { return candela[h * verticalDegrees.size() + v]; }
};

IesTable readIesFile(const std::string& path);
// The same from the text of a file, `name` naming it in errors.
IesTable parseIes(const std::string& text, const std::string& name);

}  // namespace fluence::texture
