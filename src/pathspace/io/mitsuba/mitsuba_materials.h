// Mitsuba BSDFs mapped onto pathspace materials: twosided, diffuse, conductor/roughconductor (named
// metals through the table shared with the pbrt loader), dielectric/roughdielectric map directly;
// null is an interface (it only bounds media); thindielectric, plastic/roughplastic and wrappers
// (bumpmap, mask, ...) are approximated with a warning. Mitsuba BSDFs are one-sided unless wrapped
// in `twosided`, as pathspace's diffuse lobes.
#pragma once

#include <map>
#include <string>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/mitsuba/mitsuba_textures.h"
#include "pathspace/io/mitsuba/mitsuba_xml.h"
#include "pathspace/materials/material.h"

namespace pathspace::mitsuba {

// Materials defined with an id (<bsdf id="..."> at the top level), for <ref id="..."/>.
using NamedMaterials = std::map<std::string, Material>;

// Converts the <bsdf> element `node`; textures resolve against `folder`. With `textures`, bitmap
// textures on diffuse reflectances become image textures of textures->scene (else mean colours).
Material make_bsdf(const Document& doc, const pugi::xml_node& node, const NamedMaterials& named, const std::string& folder,
                   LoadWarnings* w, TextureBinding* textures = nullptr);

// Mitsuba's default BSDF for shapes without one: one-sided diffuse of reflectance 0.5.
Material default_bsdf();

}  // namespace pathspace::mitsuba
