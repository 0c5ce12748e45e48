// SPDX-License-Identifier: MIT
#include "scene/bsdf_data.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <utility>

#include "core/conventions.h"
#include "core/error.h"
#include "scene/bsdf_xml.h"

namespace rt {

void HilbertSquare(double r, double j0, double j1, double t[2]) {
    constexpr int kOrder = 16;
    std::uint64_t d = static_cast<std::uint64_t>(r * 4294967296.0);  // 2^(2·kOrder)
    std::uint32_t x = 0, y = 0;
    for (std::uint32_t s = 1; s < (1u << kOrder); s *= 2) {
        const std::uint32_t rx = 1 & static_cast<std::uint32_t>(d / 2);
        const std::uint32_t ry = 1 & (static_cast<std::uint32_t>(d) ^ rx);
        if (ry == 0) {
            if (rx == 1) {
                x = s - 1 - x;
                y = s - 1 - y;
            }
            std::swap(x, y);
        }
        x += s * rx;
        y += s * ry;
        d /= 4;
    }
    constexpr double kCell = 1.0 / (1u << kOrder);
    t[0] = kCell * (y + j0);
    t[1] = kCell * (x + j1);
}

const BsdfComponent* BsdfData::Transmission(bool front) const {
    const BsdfComponent* near = front ? tf.get() : tb.get();
    return near ? near : (front ? tb.get() : tf.get());
}

double BsdfData::Evaluate(const Vec3& out, const Vec3& in) const {
    const bool inFront = in.z > 0.0, outFront = out.z > 0.0;
    double lamb;
    const BsdfComponent* c;
    if (inFront && outFront) {
        lamb = rLambFront;
        c = Reflection(true);
    } else if (!inFront && !outFront) {
        lamb = rLambBack;
        c = Reflection(false);
    } else {
        lamb = inFront ? tLambFront : tLambBack;
        c = Transmission(inFront);
    }
    double f = lamb / kPi;
    if (c) f += c->Value(out, in).value_or(0.0);
    return f;
}

void BsdfData::Size(double psa[2], const Vec3& v1, const Vec3* v2, bool minAndMax) const {
    psa[0] = 10.0;
    if (minAndMax) psa[1] = 0.0;
    const bool front = v1.z > 0.0;
    const BsdfComponent* r = Reflection(front);
    const BsdfComponent* t = Transmission(front);
    if (v2) ((v1.z > 0.0) != (v2->z > 0.0) ? r : t) = nullptr;
    if (!r && !t) {  // all diffuse
        psa[0] = kPi;
        if (minAndMax) psa[1] = kPi;
        return;
    }
    if (r) r->FoldProjectedSolidAngle(psa, v1, v2, minAndMax);
    if (t) t->FoldProjectedSolidAngle(psa, v1, v2, minAndMax);
}

double BsdfData::DirectHemispherical(const Vec3& in, bool transmission) const {
    const BsdfComponent* c = transmission ? Transmission(in.z > 0.0) : Reflection(in.z > 0.0);
    return c ? c->Total(in) : 0.0;
}

BsdfData ParseBsdf(std::string_view text, const std::string& path) {
    const auto fail = [&](const std::string& message) {
        ThrowUserError(FileLoc{path, 0, -1}, message);
    };
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed =
        doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!parsed) {
        throw Error(Error::Kind::User, FileLoc{path, 0, static_cast<long long>(parsed.offset)},
                    std::string("bad XML in BSDF file: ") + parsed.description());
    }
    const pugi::xml_node top = doc.document_element();
    if (std::string_view(top.name()) != "WindowElement") fail("top level node not 'WindowElement'");
    const pugi::xml_node layer = top.child("Optical").child("Layer");
    if (!layer) fail("no optical layer");
    const std::string_view structure =
        XmlText(layer.child("DataDefinition").child("IncidentDataStructure"));
    if (structure.empty()) fail("missing IncidentDataStructure");
    BsdfData bsdf;
    bsdf.name = path;
    if (EqualNoCase(structure, "Rows") || EqualNoCase(structure, "Columns")) {
        ReadKlemsLayer(layer, EqualNoCase(structure, "Rows"), path, bsdf);
    } else if (EqualNoCase(structure, "TensorTree3") || EqualNoCase(structure, "TensorTree4")) {
        ReadTreeLayer(layer, EqualNoCase(structure, "TensorTree3") ? 3 : 4, path, bsdf);
    } else {
        fail("unsupported IncidentDataStructure '" + std::string(structure) + "'");
    }
    // extract_diffuse(), then SDloadFile()'s removal of components with
    // almost nothing above their Lambertian part.
    const auto keep = [](std::unique_ptr<const BsdfComponent>& c, double& lamb) {
        if (!c) return;
        lamb = c->lambertian();
        if (c->maxHemispherical() <= 0.001) c.reset();
    };
    keep(bsdf.rf, bsdf.rLambFront);
    keep(bsdf.rb, bsdf.rLambBack);
    const bool front = bsdf.tf != nullptr, back = bsdf.tb != nullptr;
    keep(bsdf.tf, bsdf.tLambFront);
    keep(bsdf.tb, bsdf.tLambBack);
    if (front && !back) bsdf.tLambBack = bsdf.tLambFront;
    if (back && !front) bsdf.tLambFront = bsdf.tLambBack;
    return bsdf;
}

std::vector<std::string> ScatteringWarnings(const BsdfData& bsdf) {
    // SDclipName(): the file's name without folder and extension.
    std::string name = bsdf.name.substr(bsdf.name.find_last_of('/') + 1);
    if (const auto dot = name.rfind('.'); dot != std::string::npos && dot > 0) name.resize(dot);
    std::vector<std::string> warnings;
    const auto check = [&](double amount, const BsdfComponent* c, const char* what) {
        if (c) amount += c->maxHemispherical();
        if (amount <= 1.01) return;
        char text[64];
        std::snprintf(text, sizeof text, "%.1f%% ", amount * 100.0);
        warnings.push_back("BSDF \"" + name + "\" has " + text + what);
    };
    check(bsdf.rLambFront, bsdf.rf.get(), "front reflection");
    check(bsdf.rLambBack, bsdf.rb.get(), "rear reflection");
    check(bsdf.tLambFront, bsdf.tf.get(), "front transmission");
    check(bsdf.tLambBack, bsdf.tb.get(), "back transmission");
    return warnings;
}

std::shared_ptr<const BsdfData> BsdfFileCache::Load(const std::string& name,
                                                    const std::string& requestedBy,
                                                    const WarningSink& warn) {
    for (const auto& [key, bsdf] : files_) {
        if (key == name) return bsdf;
    }
    const std::optional<cal::SourceText> file = cal::FindFunctionFile(name, path_);
    if (!file) {
        throw Error(Error::Kind::System, (requestedBy.empty() ? "" : requestedBy + ": ") +
                                             "cannot find BSDF file \"" + name + "\"");
    }
    auto bsdf = std::make_shared<const BsdfData>(ParseBsdf(file->text, file->name));
    files_.emplace_back(name, bsdf);
    if (warn) {
        for (const std::string& w : ScatteringWarnings(*bsdf)) warn(w);
    }
    return bsdf;
}

}  // namespace rt
