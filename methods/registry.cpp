#include "methods/registry.h"

#include "methods/brep_guidance/brep_guidance.h"
#include "methods/cgal_triangulate/cgal_triangulate.h"
#include "methods/crest_feature/crest_feature.h"
#include "methods/liepa_cgal/liepa_cgal.h"
#include "methods/occt_fill/occt_fill.h"
#include "methods/slice_loft/slice_loft.h"
#include "methods/slice_loft/slice_loft_variants.h"

#include <stdexcept>

namespace holebench {

std::vector<std::unique_ptr<Method>> make_all_methods() {
  std::vector<std::unique_ptr<Method>> methods;
  methods.push_back(std::make_unique<LiepaCgalMethod>());
  methods.push_back(std::make_unique<BrepGuidanceMethod>());
  methods.push_back(std::make_unique<SliceLoftMethod>());
  methods.push_back(std::make_unique<SliceLoftMethod>(SliceLoftMethod::direct()));
  methods.push_back(std::make_unique<CrestFeatureMethod>());
  methods.push_back(std::make_unique<CgalTriangulateMethod>());
  methods.push_back(std::make_unique<OcctFillMethod>());
  return methods;
}

std::vector<std::unique_ptr<Method>> make_named_variants() {
  std::vector<std::unique_ptr<Method>> methods;
  methods.push_back(std::make_unique<BrepGuidanceMethod>(BrepGuidanceMethod::plus()));
  for (auto& variant : slice_loft::named_variants())
    methods.push_back(std::make_unique<SliceLoftMethod>(std::move(variant)));
  methods.push_back(std::make_unique<CrestFeatureMethod>(CrestFeatureMethod::plus()));
  methods.push_back(std::make_unique<BrepGuidanceMethod>(BrepGuidanceMethod::segmented()));
  return methods;
}

std::vector<std::unique_ptr<Method>> make_ablation_methods() {
  std::vector<std::unique_ptr<Method>> methods;
  for (auto& method : slice_loft::ablation_methods())
    methods.push_back(std::make_unique<SliceLoftMethod>(std::move(method)));
  return methods;
}

std::vector<std::unique_ptr<Method>> make_methods_run_by_name() {
  std::vector<std::unique_ptr<Method>> methods = make_named_variants();
  for (auto& method : make_ablation_methods())
    methods.push_back(std::move(method));
  return methods;
}

std::unique_ptr<Method> find_method(const std::string& id) {
  for (auto* list : {make_all_methods, make_methods_run_by_name}) {
    for (auto& method : list()) {
      if (method->id() == id)
        return std::move(method);
    }
  }
  return nullptr;
}

std::unique_ptr<Method> make_method(const std::string& id) {
  if (auto method = find_method(id))
    return method;
  throw std::invalid_argument("unknown method '" + id + "' (see `holebench list`)");
}

}  // namespace holebench
