#include "harness/outputs/file_names.h"

namespace holebench::harness {

std::string file_stem_of_id(std::string id) {
  for (char& ch : id) {
    if (ch == '/' || ch == '|')
      ch = '_';
  }
  return id;
}

}  // namespace holebench::harness
