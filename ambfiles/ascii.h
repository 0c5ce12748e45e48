// SPDX-License-Identifier: MIT
//
// The two text forms of ambient records printed and read back by lookamb
// (Radiance's src/rt/lookamb.c; radiance-notes.md §5.9): the labelled
// multi-line form and the one-line, TAB-separated `-d` form. Pure functions.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ambient/record.h"

namespace rt {

enum class AmbientTextLayout {
    Labelled,  // "Position:\t%f\t%f\t%f\n" ... "Corral:\t\t%8X\n\n"
    DataOnly,  // lookamb -d: 21 TAB-separated fields, corral as %u
};

/// One record exactly as lookamb prints it (printf %f / %e / %d / %u / %8X).
std::string FormatAmbientText(const AmbientRecord& record, AmbientTextLayout layout);

/// lookamb -r: records from text in `layout`, read as fscanf would (white space
/// separated; each labelled group's label is one skipped word). Reading stops
/// silently at the first incomplete or unparsable record, as in Radiance. Values go
/// through float like Radiance's fscanf("%f"); directions are kept as read (not
/// normalised) and re-encoded by EncodeRecord.
std::vector<AmbientRecord> ParseAmbientText(std::string_view text, AmbientTextLayout layout);

}  // namespace rt
