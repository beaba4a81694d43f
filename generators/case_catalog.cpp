#include "generators/case_catalog.h"

#include "core/boundary_loops.h"
#include "core/errors.h"
#include "core/geometry.h"
#include "generators/box_holes.h"
#include "generators/brep/brep_cases.h"
#include "generators/case_id.h"
#include "generators/crease_holes.h"
#include "generators/face_removal.h"
#include "generators/procedural_solids.h"
#include "generators/punched_case.h"
#include "generators/random.h"
#include "generators/real_holes.h"
#include "generators/vertex_noise.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>

namespace holebench::generators {

const std::vector<SizeClass>& punch_size_classes() {
  static const std::vector<SizeClass> sizes = {{"small", 0.02}, {"large", 0.08}};
  return sizes;
}

namespace {

constexpr double kStructureSizeRelDiag = 0.06;

// The models the "gear_tooth" target is listed for (punch_targets.h): gears.
bool is_gear_model(const std::string& family, const std::string& name) {
  return family == "cad" && name == "pinion";
}

std::shared_ptr<const AnalysedModel> procedural_model(const std::string& name) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const AnalysedModel>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto& model = cache[name];
  if (!model)
    model = std::make_shared<const AnalysedModel>(analyse_model(name, make_procedural_solid(name)));
  return model;
}

}  // namespace

struct CaseCatalog::State {
  CatalogOptions options;
  mutable std::once_flag listed;
  mutable std::vector<CaseDescriptor> descriptors;
  mutable std::vector<SkippedModel> skipped;
  mutable std::vector<ModelNote> model_notes;
  mutable std::mutex open_meshes_mutex;
  mutable std::map<std::string, std::shared_ptr<const ModelMesh>> open_meshes;
  void add(CaseDescriptor descriptor) const { descriptors.push_back(std::move(descriptor)); }

  static Case make_punched(const AnalysedModel& model, const PunchTarget& target,
                           const SizeClass& size, const std::string& id,
                           const std::string& family) {
    PunchedCaseOptions options;
    options.radius_rel_diag = size.radius_rel_diag;
    options.structure_size_rel_diag = kStructureSizeRelDiag;
    options.shape_seed = stable_hash(id);
    options.keep_input_regions = model.regions_are_brep_faces;
    options.shrink_to_target = family == "solid";
    Case c = make_punched_case(model, target, options);
    c.id = id;
    c.family = family;
    return c;
  }

  // Every target of a model at every size class.
  void add_punched(const std::string& family, const std::string& name,
                   std::function<std::shared_ptr<const AnalysedModel>()> load) const {
    std::shared_ptr<const AnalysedModel> model;
    try {
      model = load();
    } catch (const OpenMeshError& e) {
      if (family == "file")
        add_real_holes(name, e.read());
      else
        skipped.push_back({family + "/" + name, e.what()});
      return;
    } catch (const std::exception& e) {
      skipped.push_back({family + "/" + name, e.what()});
      return;
    }
    for (const auto& note : model->notes)
      model_notes.push_back({family + "/" + name, note});
    std::vector<PunchTarget> targets = find_punch_targets(*model);
    if (is_gear_model(family, name))
      targets.push_back(find_gear_tooth_target(*model));
    for (const auto& target : targets) {
      for (const auto& size : punch_size_classes()) {
        const std::string id = fmt::format("{}/{}/{}/{}", family, name, target.kind, size.name);
        add({id, family, target.kind,
             fmt::format("{} {}, {} hole ({} % of the diagonal)", family, name, target.kind,
                         100.0 * size.radius_rel_diag)});
      }
    }
    // B-Rep models: whole faces removed (file/<stem>/faces/<face ids>).
    if (model->regions_are_brep_faces) {
      for (const auto& removal : listed_face_removals(*model)) {
        add({fmt::format("{}/{}/faces/{}", family, name, face_set_name(removal.faces)), family,
             fmt::format("faces_k{}_{}", removal.k,
                         removal.orientation == Orientation::Inner ? "inner" : "outer"),
             fmt::format("{} {}, B-Rep face{} {} removed ({})", family, name,
                         removal.faces.size() == 1 ? "" : "s", face_set_name(removal.faces),
                         removal.combo)});
      }
    }
  }

  // The open mesh of a user's file, as read (cached: listing and making read it once; `known`,
  // where given, is the mesh prepare_cad_model read and found open).
  std::shared_ptr<const ModelMesh> open_mesh(
      const std::string& name, std::shared_ptr<const ModelMesh> known = nullptr) const {
    std::lock_guard<std::mutex> lock(open_meshes_mutex);
    if (auto it = open_meshes.find(name); it != open_meshes.end())
      return it->second;
    if (known) {
      open_meshes.emplace(name, known);
      return known;
    }
    for (const auto& source : user_mesh_sources(options.user_meshes)) {
      if (source.name != name)
        continue;
      auto mesh = std::make_shared<const ModelMesh>(read_model_mesh(source, options.prepare));
      open_meshes.emplace(name, mesh);
      return mesh;
    }
    return nullptr;
  }

  // An open mesh's real holes (real_holes.h): each as it is and enlarged by its rings.
  void add_real_holes(const std::string& name, std::shared_ptr<const ModelMesh> known) const {
    const std::string model = "file/" + name;
    const std::shared_ptr<const ModelMesh> read = open_mesh(name, std::move(known));
    for (const auto& note : read->notes)
      model_notes.push_back({model, note});
    const MeshLoops loops = classify_boundary_loops(read->mesh);
    if (loops.holes.empty()) {
      skipped.push_back({model, fmt::format("an open sheet: its {} boundary loop{} {} its border, "
                                            "not a hole (docs/generators.md, \"Real holes\")",
                                            loops.sheet_borders.size(),
                                            loops.sheet_borders.size() == 1 ? "" : "s",
                                            loops.sheet_borders.size() == 1 ? "is" : "are")});
      return;
    }
    model_notes.push_back(
        {model,
         fmt::format("an open mesh: {} real hole{} (cases {}/hole/<i>, no ground truth, "
                     "and enlarged by 1, 2, 4 rings of faces), {} sheet border{} left open",
                     loops.holes.size(), loops.holes.size() == 1 ? "" : "s", model,
                     loops.sheet_borders.size(), loops.sheet_borders.size() == 1 ? "" : "s")});
    for (std::size_t i = 0; i < loops.holes.size(); ++i) {
      add({fmt::format("{}/hole/{}", model, i), "file", "real_hole",
           fmt::format("file {}, real hole {} (no ground truth)", name, i)});
      const BoundaryLoop& loop = hole_loop(loops, static_cast<int>(i));
      for (int rings : ring_removal_counts()) {
        // Rings that take every face of a small mesh leave nothing to fill: not listed.
        if (faces_around_loop(read->mesh, loop, rings).size() >= read->mesh.n_faces())
          continue;
        add({fmt::format("{}/hole/{}/rings-{}", model, i, rings), "file",
             fmt::format("rings-{}", rings),
             fmt::format("file {}, real hole {} enlarged by {} ring{} of faces (truth: the rings)",
                         name, i, rings, rings == 1 ? "" : "s")});
      }
    }
  }

  std::optional<Case> make_real_hole(const CaseId& id) const {
    if (id.family != "file")
      return std::nullopt;
    int hole = -1;
    int rings = 0;
    try {
      std::size_t used = 0;
      hole = std::stoi(id.target, &used);
      if (used != id.target.size())
        return std::nullopt;
      if (!id.size.empty()) {
        if (id.size.rfind("rings-", 0) != 0)
          return std::nullopt;
        rings = std::stoi(id.size.substr(6), &used);
        if (used != id.size.size() - 6 || rings < 1)
          return std::nullopt;
      }
    } catch (const std::exception&) {
      return std::nullopt;
    }
    const std::shared_ptr<const ModelMesh> read = open_mesh(id.model);
    if (!read)
      return std::nullopt;
    if (find_boundary_loops(read->mesh).empty())
      throw InvalidInputError("file/" + id.model + " is closed: it has no real hole");
    return rings == 0 ? make_real_hole_case(read->mesh, hole, id.text)
                      : make_ring_removal_case(read->mesh, hole, rings, id.text);
  }

  // The loader of the model a punched id names, without listing the other families.
  std::function<std::shared_ptr<const AnalysedModel>()> loader(const std::string& family,
                                                               const std::string& name) const {
    if (family == "solid") {
      for (const auto& solid : procedural_solid_names()) {
        if (solid == name)
          return [name] { return procedural_model(name); };
      }
    }
    std::vector<CadModelSource> sources;
    if (family == "cad" && options.include_cad)
      sources = cgal_cad_models(options.cad_data_dir);
    if (family == "file")
      sources = user_mesh_sources(options.user_meshes);
    for (const auto& source : sources) {
      if (source.name == name)
        return [source, this] { return prepare_cad_model(source, options.prepare); };
    }
    return nullptr;
  }

  // Makes a case from its id alone: only the model it names is loaded.
  Case make_direct(const std::string& text) const {
    if (const auto id = parse_case_id(text)) {
      switch (id->kind) {
        case CaseIdKind::Box:
          if (auto c = make_box(*id))
            return std::move(*c);
          break;
        case CaseIdKind::Brep:
          return make_brep_case(id->text);
        case CaseIdKind::Crease:
          if (auto c = make_crease(*id))
            return std::move(*c);
          break;
        case CaseIdKind::FacesRemoved: {
          if (auto c = make_faces_removed(*id))
            return std::move(*c);
          // As before the parsed id: a face set that does not parse is tried as a punch
          // target "faces" (loading the model, whose own error comes first).
          CaseId punched = *id;
          punched.kind = CaseIdKind::Punched;
          punched.size = id->target;
          punched.target = "faces";
          if (auto c = make_punched_by_id(punched))
            return std::move(*c);
          break;
        }
        case CaseIdKind::Punched:
          if (auto c = make_punched_by_id(*id))
            return std::move(*c);
          break;
        case CaseIdKind::RealHole:
          if (auto c = make_real_hole(*id))
            return std::move(*c);
          break;
      }
    }
    throw std::invalid_argument("unknown case id '" + text + "' (see `holebench cases list`)");
  }

  static std::optional<Case> make_box(const CaseId& id) {
    for (auto target : {BoxHoleTarget::FaceInterior, BoxHoleTarget::Edge, BoxHoleTarget::Corner}) {
      if (id.target != to_string(target))
        continue;
      BoxHoleOptions box;
      box.target = target;
      return make_box_hole_case(box);
    }
    return std::nullopt;
  }

  std::optional<Case> make_crease(const CaseId& id) const {
    if (!options.include_cad)
      return std::nullopt;
    if (id.target == "concave_corner") {
      if (auto load = loader("cad", id.model)) {
        CreaseHoleOptions concave;
        concave.concave_corner = true;
        return make_crease_hole_case(*load(), 3, id.text, concave);
      }
    }
    for (const auto& creases : {"1", "2", "3"}) {
      if (id.target != creases)
        continue;
      if (auto load = loader("cad", id.model))
        return make_crease_hole_case(*load(), std::stoi(id.target), id.text);
    }
    return std::nullopt;
  }

  std::optional<Case> make_faces_removed(const CaseId& id) const {
    const auto faces = parse_face_set_name(id.target);
    if (!faces)
      return std::nullopt;
    auto load = loader(id.family, id.model);
    if (!load)
      return std::nullopt;
    Case c = make_face_removal_case(*load(), *faces, kStructureSizeRelDiag);
    c.id = id.text;
    c.family = id.family;
    return c;
  }

  std::optional<Case> make_punched_by_id(const CaseId& id) const {
    auto load = loader(id.family, id.model);
    if (!load)
      return std::nullopt;
    const auto model = load();  // throws InvalidInputError for an unusable model
    std::vector<PunchTarget> targets = find_punch_targets(*model);
    if (is_gear_model(id.family, id.model))
      targets.push_back(find_gear_tooth_target(*model));
    for (const auto& target : targets) {
      if (target.kind != id.target)
        continue;
      for (const auto& size : punch_size_classes()) {
        if (size.name == id.size)
          return make_punched(*model, target, size, id.text, id.family);
      }
    }
    return std::nullopt;
  }

  bool listed_family(const std::string& family) const {
    return options.families.empty() || std::find(options.families.begin(), options.families.end(),
                                                 family) != options.families.end();
  }

  void build() const {
    if (listed_family("box")) {
      for (auto target :
           {BoxHoleTarget::FaceInterior, BoxHoleTarget::Edge, BoxHoleTarget::Corner}) {
        const std::string kind = to_string(target);
        add({"box/" + kind, "box", kind, fmt::format("box, the skeleton's {} hole", kind)});
      }
    }
    if (listed_family("brep")) {
      for (const auto& descriptor : list_brep_cases())
        add(descriptor);
    }
    if (listed_family("solid")) {
      for (const auto& name : procedural_solid_names())
        add_punched("solid", name, loader("solid", name));
    }
    if (options.include_cad && listed_family("cad")) {
      for (const auto& source : cgal_cad_models(options.cad_data_dir)) {
        add_punched("cad", source.name, loader("cad", source.name));
      }
    }
    if (options.include_cad && listed_family("crease")) {
      // The crest-line paper's figures 10 and 13: holes across 1, 2 and 3 creases.
      for (const auto& source : cgal_cad_models(options.cad_data_dir)) {
        if (source.name != "fandisk")
          continue;
        try {
          prepare_cad_model(source, options.prepare);
        } catch (const std::exception& e) {
          skipped.push_back({"crease/" + source.name, e.what()});
          continue;
        }
        for (int creases = 1; creases <= 3; ++creases) {
          add({fmt::format("crease/{}/{}", source.name, creases), "crease",
               fmt::format("creases_{}", creases),
               fmt::format("{}, a hole across {} crease{} (crest-line paper, figures 10, 13)",
                           source.name, creases, creases == 1 ? "" : "s")});
        }
        add({fmt::format("crease/{}/concave_corner", source.name), "crease", "concave_corner",
             fmt::format("{}, a hole at a concave corner of three creases (crest-line paper, "
                         "figure 12)",
                         source.name)});
      }
    }
    if (listed_family("file")) {
      for (const auto& source : user_mesh_sources(options.user_meshes)) {
        add_punched("file", source.name, loader("file", source.name));
      }
    }
  }
};

CaseCatalog::CaseCatalog(CatalogOptions options) : state_(std::make_unique<State>()) {
  state_->options = std::move(options);
}

CaseCatalog::~CaseCatalog() = default;

const std::vector<CaseDescriptor>& CaseCatalog::cases() const {
  std::call_once(state_->listed, [this] { state_->build(); });
  return state_->descriptors;
}

const std::vector<SkippedModel>& CaseCatalog::skipped() const {
  cases();
  return state_->skipped;
}

const std::vector<ModelNote>& CaseCatalog::model_notes() const {
  cases();
  return state_->model_notes;
}

Case CaseCatalog::make(const std::string& id, std::uint64_t seed, double noise_percent) const {
  if (!(noise_percent >= 0.0))
    throw std::invalid_argument("the noise level must be >= 0");
  // Making a case never needs the whole list: only the model its id names is loaded.
  Case c = state_->make_direct(id);
  c.id = id;
  c.seed = seed;
  c.noise_percent = noise_percent;
  // The structure size the labels' decisions were taken against; for a case without labels
  // the catalog's default, relative to the diagonal.
  for (const auto& hole : c.holes) {
    if (c.parameters.structure_size == 0.0 && hole.labels) {
      c.parameters.structure_size = hole.labels->structure_size;
    }
  }
  if (c.parameters.structure_size == 0.0) {
    c.parameters.structure_size = kStructureSizeRelDiag * bounding_box_diagonal(c.complete);
  }
  NoiseOptions noise;
  noise.percent = noise_percent;
  noise.reference_length = noise_reference_length(c.complete);
  noise.seed = stable_hash(id) ^ (0x9e3779b97f4a7c15ull * (seed + 1));
  add_vertex_noise(c.input, noise);
  return c;
}

namespace {
const CaseCatalog& default_catalog() {
  static const CaseCatalog catalog;
  return catalog;
}
}  // namespace

std::vector<CaseDescriptor> list_cases() {
  return default_catalog().cases();
}

Case make_case(const std::string& id, std::uint64_t seed, double noise_percent) {
  return default_catalog().make(id, seed, noise_percent);
}

}  // namespace holebench::generators
