// The planar models the synthetic B-Rep cases are cut from (model units; the structure
// size of the cases is 1).
#pragma once

#include "generators/brep/polyhedron.h"

namespace holebench::generators::brep {

Polyhedron make_box_model();             ///< [0,6]^3
Polyhedron make_corner_notch_model();    ///< [0,10]^3 minus [5,10]^3
Polyhedron make_block_on_plate_model();  ///< plate [0,10]^2 x [0,2], block [3,7]^2 x [2,6]
/// Plate [0,10]^2 x [0,5] with a block [0,4]^2 x [5,9] on its corner (a convex-reflex-reflex
/// vertex whose three faces have outer boundaries only).
Polyhedron make_corner_block_model();
/// An L profile: base [0,6]^2 x [0,2] and wall [0,6] x [0,2] x [2,6]; a reflex valley edge.
Polyhedron make_valley_model();
Polyhedron make_pocket_model();    ///< plate [0,10]^2 x [0,3], pocket [3,7]^2 x [1,3]
Polyhedron make_l_pocket_model();  ///< plate with an L-shaped pocket (a convex inner corner)
Polyhedron make_l_boss_model();    ///< plate with an L-shaped block (a reflex inner corner)
/// Plate with a pocket in front of a block, a tunnel through the block at the pocket's
/// rim: the plate top and the pocket's back wall both have the tunnel mouth on an inner
/// boundary.
Polyhedron make_tunnel_model();
/// Plate with a pocket in front of a block and a bridge across the pocket's top.
Polyhedron make_bridge_model();
/// Plate [0,11] x [0,10] x [0,3] with a pocket [1,10] x [1,5] x [1,3] and a rib
/// [2,9] x [4,5] x [1,6] standing in it; a tunnel [3,8] x [4,5] x [3,5] runs through the
/// rib with its floor flush with the plate top, and a trench [5,8] x [4,5] x [2,3] deepens
/// the tunnel's right part. The plate top (via the tunnel floor) and the rib front (via the
/// mouth) both have the mouth's bottom edge on an inner loop; the rib keeps the rib front
/// away from the plate top everywhere else.
Polyhedron make_tunnel_rib_model();
/// Plate [0,11] x [0,10] x [0,3] with a pocket [2,9] x [1,5] x [1,3] and a rib
/// [3,8] x [4,5] x [1,6] standing in it; an L-shaped beam (bridge [4,6] x [1,4] x [2,3] with
/// its top flush with the plate top, bar [6,7] x [1,4] x [2,4]) spans from the pocket's
/// front rim to the rib front, whose inner loop is the beam's cross-section.
Polyhedron make_beam_rib_model();
/// Three thin frames through one corner V = (0, 0, 0), in the planes z = 0 (face A), x = 0
/// (face B) and y = 0 (face C): each a plate one unit thick with a window and a tongue
/// reaching into the window, the three tongues meeting at V in the corner of a cube, so that
/// V lies on an inner loop of all three faces. Each frame crosses the other two planes only
/// in their windows or beyond their outer borders (here once each: the frames are pairwise
/// linked like chain links), so A, B and C meet pairwise only along the tongues' edges at V.
/// The plates lie behind the faces (`reflex` false: V is a convex corner, all three edges
/// convex) or in front of them (the same three faces with the material on their other side:
/// all three edges reflex). Genus 3.
Polyhedron make_corner_frames_model(bool reflex);
/// Like make_corner_frames_model, but A's tongue is L-shaped with its inner corner at V (a
/// 270 degree sector) and B and C have square tongues; A passes twice through the windows of
/// B and C, which pass beyond A's outer border. With the plates behind the faces the edges
/// at V are convex (A-B, A-C) and reflex (B-C), in front of them reflex, reflex and convex.
/// Genus 3.
Polyhedron make_notch_frames_model(bool reflex);
/// A block half over a pocket: the plate top meets the vertical face in front twice along
/// one line, once reflex (at the block) and once convex (at the pocket's rim).
Polyhedron make_twisted_model();
/// A step: lower top z = 3 (y > 5), riser y = 5, upper top z = 6 (y < 5).
Polyhedron make_step_model();
/// A prism over an equilateral triangle of side 4, length 8 along x.
Polyhedron make_triangular_prism_model();
/// A pyramid over a regular n-gon (circumradius 6), apex at height 6.
Polyhedron make_pyramid_model(int sides);

}  // namespace holebench::generators::brep
