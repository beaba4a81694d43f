// CGAL seeds its process-wide default random generator (CGAL::get_default_random(), used by
// spatial sorting before Delaunay insertions, e.g. in the hole filling of liepa_cgal) from
// the clock the first time it is used. A result that depends on insertion order (a
// degenerate, co-spherical configuration) then changes from run to run. The harness calls
// this before every case generation and method run, so that the same job gives the same
// record whatever ran before it in the process and whenever it runs.
#pragma once

namespace holebench {

void seed_cgal_default_random(unsigned seed = 0);

}  // namespace holebench
