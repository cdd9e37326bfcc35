// Mitsuba participating media for the loader (mitsuba_loader.h): <medium type="homogeneous"> and
// <medium type="heterogeneous"> in Mitsuba 0.6's and 3's parameters, their <phase> (hg, isotropic)
// and volumes (constvolume, gridvolume with .vol files: mitsuba_volume_file.h) become SceneMedia
// records; and the media that shapes (interior, exterior), the sensor and emitters name, nested or
// through <ref id="...">, become SceneMedia's bindings.
#pragma once

#include <map>
#include <string>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/mitsuba/mitsuba_object.h"
#include "pathspace/io/pbrt/pbrt_media.h"
#include "pathspace/scene/scene.h"

namespace pathspace::mitsuba {

class MediaReader {
 public:
  // Volume files resolve against `folder`; media go to *media.
  MediaReader(const Document& doc, std::string folder, LoadWarnings* w, SceneMedia* media)
      : doc_(doc), folder_(std::move(folder)), w_(w), media_(media) {}

  // A top-level <medium id="...">, for the <ref id="..."/>s after it.
  void define(const pugi::xml_node& node);
  // Whether <ref> `ref` names a medium rather than a BSDF: its id is a medium's, or its name is
  // interior or exterior (an Error at the ref when that id names no medium).
  bool is_medium_ref(const pugi::xml_node& ref) const;
  // A shape's media: its nested or referenced media named interior and exterior, a side not given
  // being vacuum (as in Mitsuba 3).
  MediumInterface shape_media(const Object& shape);
  // The medium a sensor or emitter sits in (Mitsuba takes any one medium it holds), else kVacuum.
  int32_t endpoint_medium(const Object& o);

 private:
  int32_t medium_of(const pugi::xml_node& node);  // a nested <medium> or a <ref> to one
  uint32_t read(const pugi::xml_node& node);      // each element once, however many shapes use it
  uint32_t homogeneous(const Object& o, float g);
  uint32_t heterogeneous(const Object& o, float g);
  float phase_g(const Object& o);

  const Document& doc_;
  std::string folder_;
  LoadWarnings* w_;
  SceneMedia* media_;
  std::map<std::string, uint32_t> ids_;
  std::map<const void*, uint32_t> read_;  // element (pugixml's internal object) -> medium
};

}  // namespace pathspace::mitsuba
