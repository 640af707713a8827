#include "param/param_json.h"

namespace tessera {

nlohmann::ordered_json singularities_json(const CrossField& field) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const Singularity& s : field.singularities)
    list.push_back({{"vertex", s.vertex}, {"index", s.index}, {"valence", s.valence}});
  return {{"euler_characteristic", field.euler_characteristic},
          {"index_sum", field.index_sum},
          {"singularities", std::move(list)}};
}

nlohmann::ordered_json param_json(const CrossField& field, const SeamlessParam& param) {
  nlohmann::ordered_json json = singularities_json(field);
  json["flipped_triangles"] = param.flipped_triangles;
  json["flipped_outside_singular_rings"] = param.flipped_outside_singular_rings;
  json["flipped_before_injectivity"] = param.flipped_before_injectivity;
  json["max_seam_error"] = param.max_seam_error;
  json["energy"] = param.energy;
  const InjectivityReport& report = param.injectivity;
  json["injectivity"] = {{"rounds", report.rounds},
                         {"programs", report.programs},
                         {"unsolved_programs", report.unsolved_programs},
                         {"skipped_programs", report.skipped_programs},
                         {"constrained_faces", report.constrained_faces}};
  json["h"] = param.h;
  json["seconds"] = nlohmann::ordered_json::object();
  for (const StepTime& t : param.seconds) json["seconds"][t.step] = t.seconds;
  return json;
}

}  // namespace tessera
