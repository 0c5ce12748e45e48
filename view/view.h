// SPDX-License-Identifier: MIT
//
// Radiance view parameters and primary rays: the VIEW struct, getviewopt /
// sscanview / viewfile parsing, setview validation, viewray and normaspect of
// Radiance's src/common/image.c, for all six projections
//   -vtv perspective   -vtl parallel      -vta angular fisheye
//   -vth hemispherical -vts planisphere   -vtc cylindrical panorama
//
//   rt::View view = rt::ParseViewArgs({"-vf", "cornell.vf", "-vh", "40"});
//   rt::PreparedView pv = rt::SetupView(view);           // throws on a bad view
//   if (auto ray = rt::ViewRay(pv, 0.5, 0.5)) trace(ray->origin, ray->direction);
#pragma once

#include <iosfwd>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/vecmath.h"

namespace rt {

enum class ViewType : char {
    Perspective = 'v',
    Parallel = 'l',
    Angular = 'a',        // angular fisheye: image radius proportional to angle
    Hemispherical = 'h',  // image radius = sin(angle)
    Planisphere = 's',    // stereographic: image radius = tan(angle/2)
    Cylindrical = 'c',    // horizontal angle linear, vertical perspective
};

/// Radiance's VIEW as the user gives it; defaults are Radiance's STDVIEW.
/// Angles in degrees, as on the command line.
struct View {
    ViewType type = ViewType::Perspective;
    Vec3 vp{0, 0, 0};  // -vp view point
    Vec3 vd{0, 1, 0};  // -vd view direction (any length, not zero)
    Vec3 vu{0, 0, 1};  // -vu view up (not parallel to vd)
    double vh = 45;    // -vh horizontal size: degrees, or world units for -vtl
    double vv = 45;    // -vv vertical size
    double vo = 0;     // -vo fore clipping distance along the ray
    double va = 0;     // -va aft clipping distance (0: none)
    double vs = 0;     // -vs view shift, in image widths
    double vl = 0;     // -vl view lift, in image heights

    bool operator==(const View&) const = default;
};

/// The view with its image-plane vectors, as Radiance's setview() leaves it.
struct PreparedView {
    View view;         // vd and vu normalised
    Vec3 hvec;         // horizontal image vector (scaled by the plane size except -vta, -vts, -vtc)
    Vec3 vvec;         // vertical image vector (scaled except -vta, -vts)
    double hn2 = 0;    // squared horizontal plane size, Radiance's hn2
    double vn2 = 0;    // squared vertical plane size
    double vdist = 1;  // |vd| as given, Radiance's focal distance
};

struct CameraRay {
    Vec3 origin;
    Vec3 direction;      // unit length
    double maxDistance;  // distance to the aft clipping plane along `direction`, 0 = none
};

/// Radiance's getviewopt() for args[0] (one of -vt? -vp -vd -vu -vh -vv -vo -va
/// -vs -vl) and its values, plus -vf file (read with ReadViewFile). Returns the
/// number of words used after args[0], or std::nullopt when args[0] is not a view
/// option. Throws rt::Error naming the option when its values are missing or not
/// numbers, or naming the file when -vf fails.
[[nodiscard]] std::optional<int> ParseViewOption(View& view, std::span<const std::string> args);

/// Applies every word of `args` as view options (ParseViewOption), starting from
/// `start`; any other word is an error.
[[nodiscard]] View ParseViewArgs(std::span<const std::string> args, const View& start = {});
[[nodiscard]] View ParseViewArgs(const std::vector<std::string>& args, const View& start = {});

/// Radiance's sscanview(): skips a leading word that is not an option ("rview",
/// "VIEW="), applies the view options found, silently skips anything else.
/// Returns how many view options were applied.
int ScanViewString(View& view, std::string_view line);

/// Radiance's isview(): true when the line's first word, without directories,
/// starts with VIEW=, rpict, rview, rvu, rpiece, pinterp or vwrays.
[[nodiscard]] bool IsViewLine(std::string_view line);

/// The loop of ReadViewFile: applies every view line (IsViewLine) of the
/// header read from `in`, up to its first empty line, and returns how many
/// applied at least one option.
int ApplyViewHeader(std::istream& in, View& view);

/// Radiance's viewfile(): applies every view line of the file's header (text up
/// to the first blank line; a .vf file or a picture). Throws rt::Error naming the
/// file when it cannot be opened or holds no view line.
void ReadViewFile(const std::string& path, View& view);

/// Radiance's setview(): normalises, builds the image-plane vectors and rejects
/// impossible views with Radiance's messages ("illegal horizontal view size",
/// "view up parallel to view direction", ...), thrown as rt::Error.
[[nodiscard]] PreparedView SetupView(const View& view);

/// Radiance's viewray() for image coordinates (x, y) in [0,1]², x to the right,
/// y up, (0.5, 0.5) the centre (before -vs/-vl). std::nullopt outside the
/// projection (fisheye corners), where Radiance returns −1.
[[nodiscard]] std::optional<CameraRay> ViewRay(const PreparedView& view, double x, double y);

/// Radiance's viewaspect(): height/width of the image plane.
[[nodiscard]] double ViewAspect(const PreparedView& view);

/// Radiance's normaspect(): with pixelAspect > 0, shrinks xRes or yRes so pixels
/// have that aspect; with pixelAspect ≤ 0, sets it from the resolution.
void NormalizeAspect(double viewAspect, double& pixelAspect, int& xRes, int& yRes);

/// Radiance's fprintview() text: " -vtv -vp x y z -vd ... -vs 0 -vl 0" (%.6g).
[[nodiscard]] std::string FormatView(const View& view);

}  // namespace rt
