// SPDX-License-Identifier: MIT
//
// Internal to the scene module: what ParseBsdf (bsdf_data.cpp) shares with
// the readers of each kind of BSDF data, which see the XML (pugixml).
#pragma once

#include <algorithm>
#include <cctype>
#include <pugixml.hpp>
#include <string>
#include <string_view>

#include "scene/bsdf_data.h"

namespace rt {

inline bool EqualNoCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

/// An element's text without surrounding white space (ezxml_txt()).
inline std::string_view XmlText(const pugi::xml_node& node) {
    std::string_view t = node.child_value();
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.front()))) t.remove_prefix(1);
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.remove_suffix(1);
    return t;
}

/// Reads a layer's Klems matrices into `bsdf` (bsdf_m.c's SDloadMtx(), up
/// to extract_diffuse(), which ParseBsdf applies): the angle bases the
/// layer's DataDefinition defines, then each Visible WavelengthDataBlock,
/// incident directions in rows (`rows`) or columns. Throws rt::Error (User,
/// "path: ..."): a missing or unknown basis, too few or bad values.
void ReadKlemsLayer(const pugi::xml_node& layer, bool rows, const std::string& path,
                    BsdfData& bsdf);

/// Reads a layer's tensor trees of rank 3 or 4 into `bsdf` (bsdf_t.c's
/// SDloadTre(), up to extract_diffuse()). Throws rt::Error (User): a missing or
/// unknown angle basis, a malformed tree ("path: byte N: ...").
void ReadTreeLayer(const pugi::xml_node& layer, int rank, const std::string& path, BsdfData& bsdf);

}  // namespace rt
