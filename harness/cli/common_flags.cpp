#include "harness/cli/common_flags.h"

namespace holebench::harness::cli {

void add_catalog_flags(CLI::App* command, generators::CatalogOptions& catalog, bool& no_cad) {
  command
      ->add_option("--mesh", catalog.user_meshes,
                   "Your own mesh or B-Rep file or folder (OFF/OBJ/STL/PLY, STEP/IGES/BREP), "
                   "punched like the CAD models; an open mesh gives its real holes instead "
                   "(file/<stem>/hole/<i>, no ground truth, and .../rings-<r> with its rings "
                   "removed as truth); repeatable. Its cases are file/<stem>/...")
      ->check(CLI::ExistingPath);
  command
      ->add_option("--brep-deflection", catalog.prepare.tessellation.linear_deflection_rel_diag,
                   "Tessellation of B-Rep files: the largest distance between a triangle and "
                   "its face, relative to the bounding-box diagonal")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command->add_flag("--no-cad", no_cad,
                    "Leave out the CGAL data set's CAD models (faster listing)");
  command->add_option("--cad-dir", catalog.cad_data_dir,
                      "Folder with the CGAL data set's meshes (default: extracted by the build; "
                      "or $HOLEBENCH_CAD_DIR)");
}

}  // namespace holebench::harness::cli
