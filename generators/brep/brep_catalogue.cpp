#include "generators/brep/brep_catalogue.h"

#include "generators/brep/brep_models.h"

#include <fmt/format.h>

#include <utility>

namespace holebench::generators::brep {
namespace {

// The stem's first two parts: "k2/inner/convex" -> "k2/inner".
std::string kind_of(const std::string& stem) {
  const auto slash = stem.find('/');
  return stem.substr(0, slash) + "/" +
         stem.substr(slash + 1, stem.find('/', slash + 1) - slash - 1);
}

// One recipe, its fields set by name. Unless set, the combination is the stem and the target
// is what the hole is made at: "face_interior", "edge" or "corner" for a ball, "faces" for a
// face removal.
class Entry {
 public:
  Entry(std::string stem, std::variant<BallSpec, RemovalSpec> spec) {
    recipe_.stem = std::move(stem);
    recipe_.spec = std::move(spec);
  }

  // A ball hole: its centre.
  Entry& around_face_point(Point p) { return around(p, Target::Face); }
  Entry& around_edge_point(Point p) { return around(p, Target::Edge); }
  Entry& around_vertex(Point p) { return around(p, Target::Vertex); }
  Entry& small_radius(double r) {
    std::get<BallSpec>(recipe_.spec).small_radius = r;
    return *this;
  }
  Entry& large_radius(double r) {
    std::get<BallSpec>(recipe_.spec).large_radius = r;
    return *this;
  }

  // A face removal: a point inside each face named.
  Entry& removing_faces_at(std::vector<Point> faces) {
    return name_faces(std::move(faces), NamedFaces::Removed);
  }
  Entry& keeping_only_faces_at(std::vector<Point> faces) {
    return name_faces(std::move(faces), NamedFaces::Kept);
  }

  Entry& target(std::string target) {
    recipe_.target = std::move(target);
    return *this;
  }
  Entry& combo(std::string combo) {
    recipe_.combo = std::move(combo);
    return *this;
  }
  Entry& weak_spot(std::string weak_spot) {
    recipe_.weak_spot = std::move(weak_spot);
    return *this;
  }
  Entry& described_as(std::string description) {
    recipe_.description = std::move(description);
    return *this;
  }

  operator Recipe() const {
    Recipe recipe = recipe_;
    if (recipe.combo.empty())
      recipe.combo = recipe.stem;
    if (recipe.target.empty())
      recipe.target = default_target();
    recipe.kind = kind_of(recipe.stem);
    return recipe;
  }

 private:
  Entry& around(Point center, Target target) {
    auto& ball = std::get<BallSpec>(recipe_.spec);
    ball.center = center;
    ball.target = target;
    return *this;
  }

  Entry& name_faces(std::vector<Point> faces, NamedFaces named) {
    auto& removal = std::get<RemovalSpec>(recipe_.spec);
    removal.faces = std::move(faces);
    removal.named = named;
    return *this;
  }

  std::string default_target() const {
    const auto* ball = std::get_if<BallSpec>(&recipe_.spec);
    if (!ball)
      return "faces";
    if (ball->target == Target::Face)
      return "face_interior";
    return ball->target == Target::Edge ? "edge" : "corner";
  }

  Recipe recipe_;
};

Entry ball(std::string stem, std::function<Polyhedron()> model) {
  BallSpec spec;
  spec.model = std::move(model);
  return Entry(std::move(stem), std::move(spec));
}

Entry removal(std::string stem, std::function<Polyhedron()> model) {
  RemovalSpec spec;
  spec.model = std::move(model);
  return Entry(std::move(stem), std::move(spec));
}

// The frame models with their material behind the faces (convex) or in front (reflex).
Polyhedron convex_corner_frames() {
  return make_corner_frames_model(/*reflex=*/false);
}
Polyhedron reflex_corner_frames() {
  return make_corner_frames_model(/*reflex=*/true);
}
Polyhedron convex_notch_frames() {
  return make_notch_frames_model(/*reflex=*/false);
}
Polyhedron reflex_notch_frames() {
  return make_notch_frames_model(/*reflex=*/true);
}

std::vector<Recipe> make_recipes() {
  std::vector<Recipe> r;
  // Inner holes: a ball around a face point (k = 1), an edge point (k = 2), a vertex (k = 3).
  r.push_back(ball("k1/inner", make_box_model)
                  .around_face_point({3, 3, 6})
                  .small_radius(0.25)
                  .large_radius(1.0)
                  .described_as("box, face interior"));
  r.push_back(ball("k2/inner/convex", make_box_model)
                  .around_edge_point({3.5, 0, 6})
                  .described_as("box, convex edge"));
  r.push_back(ball("k2/inner/reflex", make_corner_notch_model)
                  .around_edge_point({5, 5, 7.5})
                  .described_as("corner notch, reflex edge"));
  r.push_back(ball("k3/inner/convex-convex-convex", make_box_model)
                  .around_vertex({6, 6, 6})
                  .described_as("box corner"));
  r.push_back(ball("k3/inner/convex-convex-reflex", make_corner_notch_model)
                  .around_vertex({5, 5, 10})
                  .described_as("corner notch, outer vertex"));
  r.push_back(ball("k3/inner/convex-reflex-reflex", make_block_on_plate_model)
                  .around_vertex({3, 3, 2})
                  .described_as("block on a plate, foot of a vertical block edge"));
  r.push_back(ball("k3/inner/reflex-reflex-reflex", make_corner_notch_model)
                  .around_vertex({5, 5, 5})
                  .described_as("corner notch, inner vertex"));

  // Outer holes: whole faces removed.
  r.push_back(removal("k1/outer/outer", make_box_model)
                  .keeping_only_faces_at({{3, 3, 6}})
                  .described_as("box with only its top face kept"));
  r.push_back(removal("k2/outer/convex/outer-outer", make_box_model)
                  .keeping_only_faces_at({{3, 3, 6}, {3, 0, 3}})
                  .described_as("box with only two faces along a convex edge (a ridge) kept"));
  r.push_back(
      removal("k2/outer/reflex/outer-outer", make_valley_model)
          .keeping_only_faces_at({{3, 4, 2}, {3, 2, 4}})
          .described_as("L profile with only the two faces along its reflex edge (a valley) kept"));
  r.push_back(removal("k2/outer/convex/inner-outer", make_pocket_model)
                  .removing_faces_at({{5, 5, 1}, {3, 5, 2}, {7, 5, 2}, {5, 7, 2}})
                  .described_as("plate with a pocket: floor and three walls removed"));
  r.push_back(removal("k2/outer/reflex/inner-outer", make_block_on_plate_model)
                  .removing_faces_at({{5, 5, 6}, {3, 5, 4}, {7, 5, 4}, {5, 7, 4}})
                  .described_as("block on a plate: top and three walls removed"));
  // k = 3, every face on its outer boundary: the three faces at a vertex kept.
  r.push_back(removal("k3/outer/convex-convex-convex/outer-outer-outer", make_box_model)
                  .keeping_only_faces_at({{3, 3, 6}, {6, 3, 3}, {3, 6, 3}})
                  .described_as("box, three faces of a corner kept"));
  r.push_back(removal("k3/outer/convex-convex-reflex/outer-outer-outer", make_corner_notch_model)
                  .keeping_only_faces_at({{2, 2, 10}, {5, 7, 7}, {7, 5, 7}})
                  .described_as("corner notch, the three faces of its outer vertex kept"));
  r.push_back(removal("k3/outer/convex-reflex-reflex/outer-outer-outer", make_corner_block_model)
                  .keeping_only_faces_at({{7, 7, 5}, {4, 2, 7}, {2, 4, 7}})
                  .described_as("block on a plate's corner, the three faces at its foot kept"));
  r.push_back(removal("k3/outer/reflex-reflex-reflex/outer-outer-outer", make_corner_notch_model)
                  .keeping_only_faces_at({{7, 7, 5}, {5, 7, 7}, {7, 5, 7}})
                  .described_as("corner notch, the three faces of its inner vertex kept"));
  // k = 3, one face on its inner boundary: a pocket or a block with two adjacent walls kept.
  r.push_back(removal("k3/outer/convex-convex-convex/inner-outer-outer", make_l_pocket_model)
                  .removing_faces_at({{3, 3, 1}, {2, 4, 2}, {4, 2, 2}, {8, 3, 2}, {3, 8, 2}})
                  .described_as("L-shaped pocket: floor and all walls but the two at its convex "
                                "inner corner removed"));
  r.push_back(removal("k3/outer/convex-convex-reflex/inner-outer-outer", make_pocket_model)
                  .removing_faces_at({{5, 5, 1}, {7, 5, 2}, {5, 7, 2}})
                  .described_as("pocket: floor and two adjacent walls removed"));
  r.push_back(removal("k3/outer/convex-reflex-reflex/inner-outer-outer", make_block_on_plate_model)
                  .removing_faces_at({{5, 5, 6}, {7, 5, 4}, {5, 7, 4}})
                  .described_as("block on a plate: top and two adjacent walls removed"));
  r.push_back(removal("k3/outer/reflex-reflex-reflex/inner-outer-outer", make_l_boss_model)
                  .removing_faces_at({{4, 4, 6}, {2, 4, 4}, {4, 2, 4}, {8, 3, 4}, {3, 8, 4}})
                  .described_as("L-shaped block: top and all walls but the two at its reflex "
                                "inner corner removed"));

  // Outer holes on two inner boundaries: a rib standing in a pocket, with a tunnel through it
  // (floor flush with the plate top) or an L-shaped beam from the pocket's front rim into it
  // (top flush with the plate top). The rib keeps its front away from the plate top except
  // along the tunnel floor's / the beam top's edge, so that the two faces meet along one
  // edge only.
  r.push_back(removal("k2/outer/convex/inner-inner", make_tunnel_rib_model)
                  .keeping_only_faces_at({{0.5, 0.5, 3}, {2.5, 4, 2}})
                  .described_as("rib in a pocket, tunnel through the rib: only the plate top (its "
                                "pocket rim and the tunnel floor) and the rib front (its mouth) "
                                "kept"));
  r.push_back(removal("k3/outer/convex-convex-reflex/inner-inner-outer", make_tunnel_rib_model)
                  .keeping_only_faces_at({{0.5, 0.5, 3}, {2.5, 4, 2}, {3, 4.5, 4}})
                  .described_as("rib in a pocket, tunnel through the rib: plate top, rib front "
                                "and the tunnel's left wall kept (mouth corner on the tunnel "
                                "floor)"));
  r.push_back(removal("k3/outer/convex-convex-convex/inner-inner-outer", make_tunnel_rib_model)
                  .keeping_only_faces_at({{0.5, 0.5, 3}, {2.5, 4, 2}, {5, 4.5, 2.5}})
                  .described_as("rib in a pocket, tunnel through the rib with a trench in its "
                                "floor: plate top, rib front and the trench's left wall kept (the "
                                "mouth's reflex corner at the trench's edge)"));
  r.push_back(removal("k2/outer/reflex/inner-inner", make_beam_rib_model)
                  .keeping_only_faces_at({{0.5, 0.5, 3}, {3.5, 4, 2}})
                  .described_as("rib in a pocket, beam from the pocket rim into the rib: only the "
                                "plate top (its pocket rim and the beam top) and the rib front "
                                "kept"));
  r.push_back(removal("k3/outer/convex-reflex-reflex/inner-inner-outer", make_beam_rib_model)
                  .keeping_only_faces_at({{0.5, 0.5, 3}, {3.5, 4, 2}, {4, 2.5, 2.5}})
                  .described_as("rib in a pocket, beam from the pocket rim into the rib: plate "
                                "top, rib front and the beam's left side kept"));
  r.push_back(removal("k3/outer/reflex-reflex-reflex/inner-inner-outer", make_beam_rib_model)
                  .keeping_only_faces_at({{0.5, 0.5, 3}, {3.5, 4, 2}, {6, 2.5, 3.5}})
                  .described_as("rib in a pocket, L-shaped beam from the pocket rim into the rib: "
                                "plate top, rib front and the face of the beam's raised bar above "
                                "the beam top kept (reflex corner of the beam's cross-section)"));

  // Outer holes on three inner boundaries: three thin frames through one corner V, each
  // with a tongue reaching into its window, the tongues meeting at V; each frame crosses the
  // other two planes only in their windows or beyond their borders. The same three faces with
  // the material behind or in front of them give the convex and the reflex signatures.
  r.push_back(removal("k3/outer/convex-convex-convex/inner-inner-inner", convex_corner_frames)
                  .keeping_only_faces_at({{-2, -2, 0}, {0, -2, -2}, {-2, 0, -2}})
                  .described_as("three thin frames through a convex corner, each with a tongue "
                                "into its window, the tongues meeting at the corner: only the "
                                "three faces at the corner kept"));
  r.push_back(removal("k3/outer/convex-convex-reflex/inner-inner-inner", convex_notch_frames)
                  .keeping_only_faces_at({{-2, -2, 0}, {0, 2, -2}, {2, 0, -2}})
                  .described_as("three thin frames through a notch's outer corner (an L-shaped "
                                "tongue and two square tongues): only the three faces at the "
                                "corner kept"));
  r.push_back(removal("k3/outer/convex-reflex-reflex/inner-inner-inner", reflex_notch_frames)
                  .keeping_only_faces_at({{-2, -2, 0}, {0, 2, -2}, {2, 0, -2}})
                  .described_as("three thin frames through a notch's corner, the material in "
                                "front of the faces (an L-shaped tongue and two square tongues): "
                                "only the three faces at the corner kept"));
  r.push_back(removal("k3/outer/reflex-reflex-reflex/inner-inner-inner", reflex_corner_frames)
                  .keeping_only_faces_at({{-2, -2, 0}, {0, -2, -2}, {-2, 0, -2}})
                  .described_as("three thin frames through a reflex corner (the material in "
                                "front of the faces), each with a tongue into its window: only "
                                "the three faces at the corner kept"));

  // Variants.
  r.push_back(removal("weak/multiple-inner-boundaries", make_tunnel_rib_model)
                  .removing_faces_at({{1.5, 2, 1},
                                      {5, 1, 2},
                                      {1, 3, 2},
                                      {10, 3, 2},
                                      {1.5, 5, 2},
                                      {9.5, 5, 2},
                                      {2.5, 5, 4},
                                      {2, 4.5, 4},
                                      {9, 4.5, 4},
                                      {3, 4.5, 4},
                                      {5, 4.5, 5},
                                      {8, 4.5, 4},
                                      {6.5, 4.5, 2},
                                      {5, 4.5, 2.5},
                                      {6.5, 5, 2.5}})
                  .combo("k2/outer/convex/inner-inner")
                  .weak_spot("multiple_inner_boundaries")
                  .described_as("rib in a pocket, tunnel through the rib, as a scan from the "
                                "front sees it: the pocket, the tunnel, the trench and the rib's "
                                "back and sides missing, everything else kept"));
  r.push_back(removal("k3/linearly-dependent", make_triangular_prism_model)
                  .removing_faces_at({{8, 2, 1}})
                  .combo("k3/outer/convex-convex-convex/outer-outer-outer")
                  .described_as("triangular prism, one end cap removed: three faces whose planes "
                                "share no point"));
  r.push_back(removal("k4/step-parallel-faces", make_step_model)
                  .keeping_only_faces_at({{5, 2, 6}, {5, 5, 4}, {5, 7, 3}})
                  .combo("k4/outer/convex-convex-reflex-reflex/outer-outer-outer-outer")
                  .described_as("step: only upper top, riser and lower top kept; the riser is "
                                "visited twice"));
  r.push_back(
      removal("weak/twisted-face", make_twisted_model)
          .keeping_only_faces_at(
              {{0.5, 0.5, 3}, {3, 4, 4}, {0, 5, 1}, {10, 5, 1}, {5, 0, 1}, {5, 10, 1}, {5, 5, 0}})
          .combo("k2/outer/convex-reflex/inner-outer")
          .weak_spot("twisted_face")
          .described_as("plate top twisted around a vertical face: they meet reflex at a "
                        "block and convex at a pocket rim on the same line"));
  for (int sides : {4, 5, 6}) {
    std::string convexities;
    for (int i = 0; i < sides; ++i)
      convexities += i == 0 ? "convex" : "-convex";
    r.push_back(
        ball(fmt::format("k{}/pyramid-apex", sides), [sides] { return make_pyramid_model(sides); })
            .around_vertex({0, 0, 6})
            .small_radius(0.3)
            .target("apex")
            .combo(fmt::format("k{}/inner/{}", sides, convexities))
            .described_as(fmt::format("apex of a pyramid with {} sides", sides)));
  }
  return r;
}

}  // namespace

const std::vector<Recipe>& brep_recipes() {
  static const std::vector<Recipe> all = make_recipes();
  return all;
}

}  // namespace holebench::generators::brep
