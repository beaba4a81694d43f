// The PLY reader (core/mesh_io.h): ASCII and binary, little and big endian, errors naming the line
// or the byte.
#include "core/mesh_io/parsing.h"
#include "core/mesh_io/readers.h"

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

namespace holebench::mesh_io {

namespace {

enum class PlyType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool ply_type(std::string_view name, PlyType& type) {
  static const std::pair<std::string_view, PlyType> kNames[] = {
      {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
      {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
      {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (const auto& [n, t] : kNames) {
    if (n == name) {
      type = t;
      return true;
    }
  }
  return false;
}

int ply_size(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 1;
}

bool ply_integral(PlyType t) {
  return t != PlyType::Float32 && t != PlyType::Float64;
}

struct PlyProperty {
  std::string name;
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;
  PlyType type = PlyType::Float32;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::size_t line = 0;  ///< header line that declares it
  std::vector<PlyProperty> properties;
};

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::size_t data_offset = 0;
};

PlyHeader read_ply_header(const std::string& src, LineReader& lines) {
  std::string_view line;
  Tokens tok;
  lines.next(line);
  split(line, tok);
  if (tok.size() != 1 || tok[0] != "ply") {
    fail(src, "not a PLY file: it does not start with the line 'ply'");
  }
  PlyHeader header;
  bool has_format = false;
  bool ended = false;
  while (lines.next(line)) {
    split(line, tok);
    if (tok.empty())
      continue;
    const std::string_view keyword = tok[0];
    if (keyword == "end_header") {
      ended = true;
      break;
    }
    if (keyword == "comment" || keyword == "obj_info")
      continue;
    if (keyword == "format") {
      if (tok.size() < 2)
        fail(src, fmt::format("line {}: 'format' without a value", lines.line()));
      if (tok[1] == "ascii") {
        header.format = PlyFormat::Ascii;
      } else if (tok[1] == "binary_little_endian") {
        header.format = PlyFormat::BinaryLittleEndian;
      } else if (tok[1] == "binary_big_endian") {
        header.format = PlyFormat::BinaryBigEndian;
      } else {
        fail(src, fmt::format("line {}: unknown PLY format {} (expected ascii, "
                              "binary_little_endian or binary_big_endian)",
                              lines.line(), show(tok[1])));
      }
      has_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      if (tok.size() != 3 || !parse_uint64(tok[2], element.count)) {
        fail(src, fmt::format("line {}: expected 'element <name> <count>'", lines.line()));
      }
      element.name = std::string(tok[1]);
      element.line = lines.line();
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) {
        fail(src, fmt::format("line {}: 'property' before any 'element'", lines.line()));
      }
      PlyProperty property;
      std::string_view type_name;
      if (tok.size() >= 2 && tok[1] == "list") {
        if (tok.size() != 5) {
          fail(src, fmt::format("line {}: expected 'property list <count type> <index type> "
                                "<name>'",
                                lines.line()));
        }
        property.is_list = true;
        if (!ply_type(tok[2], property.count_type)) {
          fail(src, fmt::format("line {}: unknown property type {}", lines.line(), show(tok[2])));
        }
        if (!ply_integral(property.count_type)) {
          fail(src, fmt::format("line {}: the count type of a list must be an integer type, "
                                "found {}",
                                lines.line(), show(tok[2])));
        }
        type_name = tok[3];
        property.name = std::string(tok[4]);
      } else {
        if (tok.size() != 3) {
          fail(src, fmt::format("line {}: expected 'property <type> <name>'", lines.line()));
        }
        type_name = tok[1];
        property.name = std::string(tok[2]);
      }
      if (!ply_type(type_name, property.type)) {
        fail(src, fmt::format("line {}: unknown property type {}", lines.line(), show(type_name)));
      }
      header.elements.back().properties.push_back(std::move(property));
    } else {
      fail(src, fmt::format("line {}: unexpected PLY header line starting with {}", lines.line(),
                            show(keyword)));
    }
  }
  if (!ended) {
    fail(src,
         fmt::format("line {}: truncated: the PLY header has no 'end_header' line", lines.line()));
  }
  if (!has_format)
    fail(src, "the PLY header has no 'format' line");
  header.data_offset = lines.position();
  return header;
}

/// Where the data of interest sits in a PLY header's elements.
struct PlyLayout {
  const PlyElement* vertex = nullptr;
  const PlyElement* face = nullptr;
  std::array<std::size_t, 3> xyz{};      ///< property indices in the vertex element
  std::size_t indices = 0;               ///< list property index in the face element
  std::size_t region = std::size_t(-1);  ///< "region" property index, or -1
};

PlyLayout ply_layout(const std::string& src, const PlyHeader& header) {
  PlyLayout layout;
  for (const PlyElement& element : header.elements) {
    if (element.name != "vertex" && element.name != "face")
      continue;
    const PlyElement*& slot = element.name == "vertex" ? layout.vertex : layout.face;
    if (slot != nullptr) {
      fail(src, fmt::format("line {}: a second '{}' element", element.line, element.name));
    }
    slot = &element;
  }
  if (layout.vertex == nullptr)
    fail(src, "the PLY header declares no 'vertex' element");
  const char* axes[] = {"x", "y", "z"};
  for (int c = 0; c < 3; ++c) {
    const auto& props = layout.vertex->properties;
    const auto it = std::find_if(props.begin(), props.end(), [&](const PlyProperty& p) {
      return !p.is_list && p.name == axes[c];
    });
    if (it == props.end()) {
      fail(src, fmt::format("line {}: the 'vertex' element has no '{}' property",
                            layout.vertex->line, axes[c]));
    }
    layout.xyz[c] = static_cast<std::size_t>(it - props.begin());
  }
  if (layout.face != nullptr) {
    const auto& props = layout.face->properties;
    const auto it = std::find_if(props.begin(), props.end(), [](const PlyProperty& p) {
      return p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index");
    });
    if (it == props.end()) {
      fail(src, fmt::format("line {}: the 'face' element has no 'vertex_indices' list property",
                            layout.face->line));
    }
    if (!ply_integral(it->type)) {
      fail(src, fmt::format("line {}: the vertex indices of the 'face' element must have an "
                            "integer type",
                            layout.face->line));
    }
    layout.indices = static_cast<std::size_t>(it - props.begin());
    for (std::size_t k = 0; k < props.size(); ++k) {
      if (!props[k].is_list && props[k].name == "region")
        layout.region = k;
    }
  }
  return layout;
}

/// PLY values from ASCII lines, one element per line.
class PlyAsciiSource {
 public:
  PlyAsciiSource(const std::string& src, LineReader& lines) : src_(src), lines_(lines) {}

  void begin_element(const PlyElement& element) { element_ = &element; }
  void begin_item(std::uint64_t index) {
    index_ = index;
    if (!lines_.next_tokens(tokens_, false)) {
      fail(src_, fmt::format("line {}: truncated: the file ends after {} of {} '{}' elements",
                             lines_.line(), index, element_->count, element_->name));
    }
    next_ = 0;
  }
  double value(PlyType type) {
    need(1);
    const std::string_view tok = tokens_[next_++];
    if (ply_integral(type)) {
      long long v = 0;
      if (!parse_int(tok, v)) {
        fail(src_, fmt::format("{}: cannot parse {} as an integer ('{}' element {})", where(),
                               show(tok), element_->name, index_));
      }
      return static_cast<double>(v);
    }
    double v = 0;
    const std::string error = parse_double(tok, v);
    if (!error.empty()) {
      fail(src_, fmt::format("{}: {} ('{}' element {})", where(), error, element_->name, index_));
    }
    return v;
  }
  void require(std::uint64_t n, PlyType) { need(n); }
  void need(std::uint64_t n) {
    if (n > tokens_.size() - next_) {
      fail(src_, fmt::format("{}: '{}' element {} has too few values for the properties the "
                             "header declares",
                             where(), element_->name, index_));
    }
  }
  void skip_list(std::uint64_t n, PlyType) {
    need(n);
    next_ += static_cast<std::size_t>(n);
  }
  void end_item() {
    if (next_ < tokens_.size()) {
      fail(src_, fmt::format("{}: '{}' element {} has {} values, more than the {} the header "
                             "declares",
                             where(), element_->name, index_, tokens_.size(), next_));
    }
  }
  std::string where() const { return fmt::format("line {}", lines_.line()); }

 private:
  const std::string& src_;
  LineReader& lines_;
  const PlyElement* element_ = nullptr;
  std::uint64_t index_ = 0;
  Tokens tokens_;
  std::size_t next_ = 0;
};

/// PLY values from binary data of either byte order.
class PlyBinarySource {
 public:
  PlyBinarySource(const std::string& src, std::string_view data, std::size_t offset,
                  bool big_endian)
      : src_(src), data_(data), pos_(offset), big_endian_(big_endian) {}

  void begin_element(const PlyElement& element) {
    element_ = &element;
    std::uint64_t stride = 0;
    for (const PlyProperty& p : element.properties) {
      if (p.is_list)
        return;  // variable size: checked value by value
      stride += static_cast<std::uint64_t>(ply_size(p.type));
    }
    const std::uint64_t left = data_.size() - pos_;
    if (stride > 0 && element.count > left / stride) {
      fail(src_, fmt::format("byte {}: truncated: the file ends after {} of {} '{}' elements "
                             "({} bytes each)",
                             data_.size(), left / stride, element.count, element.name, stride));
    }
  }
  void begin_item(std::uint64_t index) { index_ = index; }
  double value(PlyType type) {
    const int size = ply_size(type);
    require_bytes(static_cast<std::uint64_t>(size));
    at_ = pos_;
    const std::uint64_t u = read_unsigned(data_.data() + pos_, size, big_endian_);
    pos_ += static_cast<std::size_t>(size);
    switch (type) {
      case PlyType::Int8:
        return static_cast<std::int8_t>(static_cast<std::uint8_t>(u));
      case PlyType::UInt8:
        return static_cast<std::uint8_t>(u);
      case PlyType::Int16:
        return static_cast<std::int16_t>(static_cast<std::uint16_t>(u));
      case PlyType::UInt16:
        return static_cast<std::uint16_t>(u);
      case PlyType::Int32:
        return static_cast<std::int32_t>(static_cast<std::uint32_t>(u));
      case PlyType::UInt32:
        return static_cast<std::uint32_t>(u);
      case PlyType::Float32: {
        const auto bits = static_cast<std::uint32_t>(u);
        float f = 0;
        std::memcpy(&f, &bits, 4);
        return f;
      }
      case PlyType::Float64: {
        double d = 0;
        std::memcpy(&d, &u, 8);
        return d;
      }
    }
    return 0;
  }
  void require(std::uint64_t n, PlyType type) {
    const auto size = static_cast<std::uint64_t>(ply_size(type));
    if (n > (data_.size() - pos_) / size)
      truncated();
  }
  void skip_list(std::uint64_t n, PlyType type) {
    require(n, type);
    pos_ += static_cast<std::size_t>(n * static_cast<std::uint64_t>(ply_size(type)));
  }
  void end_item() {}
  std::string where() const { return fmt::format("byte {}", at_); }

 private:
  void require_bytes(std::uint64_t n) {
    if (n > data_.size() - pos_)
      truncated();
  }
  [[noreturn]] void truncated() const {
    fail(src_, fmt::format("byte {}: truncated: the file ends inside '{}' element {} of {}",
                           data_.size(), element_->name, index_, element_->count));
  }

  const std::string& src_;
  std::string_view data_;
  std::size_t pos_;
  std::size_t at_ = 0;  ///< offset of the last value read
  bool big_endian_;
  const PlyElement* element_ = nullptr;
  std::uint64_t index_ = 0;
};

template <class Source>
void read_ply_body(const std::string& src, Source& source, const PlyHeader& header,
                   const PlyLayout& layout, TriangleSoup& soup) {
  const long long vertex_count = static_cast<long long>(
      std::min<std::uint64_t>(layout.vertex->count, std::numeric_limits<long long>::max()));
  std::vector<int> corners;
  for (const PlyElement& element : header.elements) {
    if (element.properties.empty())
      continue;  // nothing stored per element
    source.begin_element(element);
    const bool is_vertex = &element == layout.vertex;
    const bool is_face = &element == layout.face;
    for (std::uint64_t i = 0; i < element.count; ++i) {
      source.begin_item(i);
      Point p(0, 0, 0);
      int region = kNoRegion;
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const PlyProperty& property = element.properties[k];
        if (!property.is_list) {
          const double v = source.value(property.type);
          if (is_vertex) {
            for (int c = 0; c < 3; ++c) {
              if (layout.xyz[c] == k)
                p[c] = v;
            }
          } else if (is_face && k == layout.region) {
            if (!(v == std::floor(v) && v >= std::numeric_limits<int>::min() &&
                  v <= std::numeric_limits<int>::max())) {
              fail(src,
                   fmt::format("{}: region {} of face {} is not an int", source.where(), v, i));
            }
            region = static_cast<int>(v);
          }
          continue;
        }
        const double count = source.value(property.count_type);
        if (count < 0) {
          fail(src, fmt::format("{}: negative list length {} in '{}' element {}", source.where(),
                                count, element.name, i));
        }
        const auto n = static_cast<std::uint64_t>(count);
        if (!is_face || k != layout.indices) {
          source.skip_list(n, property.type);
          continue;
        }
        if (n < 3) {
          fail(src, fmt::format("{}: face {} has {} vertices; a face needs at least 3",
                                source.where(), i, n));
        }
        source.require(n, property.type);
        corners.clear();
        for (std::uint64_t j = 0; j < n; ++j) {
          const double v = source.value(property.type);
          if (v < 0 || v >= static_cast<double>(vertex_count)) {
            fail(src, fmt::format("{}: face {} references vertex {}, but there are {} vertices",
                                  source.where(), i, v, vertex_count));
          }
          corners.push_back(static_cast<int>(v));
        }
      }
      source.end_item();
      if (is_vertex)
        soup.points.push_back(p);
      if (is_face) {
        add_fan(soup, corners);
        if (layout.region != std::size_t(-1))
          soup.regions.resize(soup.triangles.size(), region);
      }
    }
  }
}

}  // namespace

TriangleSoup read_ply(const std::string& src, std::string_view data) {
  LineReader lines(data);
  const PlyHeader header = read_ply_header(src, lines);
  const PlyLayout layout = ply_layout(src, header);
  TriangleSoup soup;
  if (header.format == PlyFormat::Ascii) {
    check_text(src, data, "ASCII PLY");
    PlyAsciiSource source(src, lines);
    read_ply_body(src, source, header, layout, soup);
  } else {
    PlyBinarySource source(src, data, header.data_offset,
                           header.format == PlyFormat::BinaryBigEndian);
    read_ply_body(src, source, header, layout, soup);
  }
  return soup;
}

}  // namespace holebench::mesh_io
