#include "core/occt/brep_file_reader.h"

#include "core/errors.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IGESControl_Reader.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Shape.hxx>
#include <XSControl_Reader.hxx>

#include <fmt/format.h>

#include <iostream>
#include <mutex>
#include <string>

namespace holebench::occt {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw InvalidInputError(fmt::format("{}: {}", path.string(), what));
}

BrepFormat format_of(const std::filesystem::path& path) {
  if (const auto format = brep_format(path))
    return *format;
  fail(path, "unknown B-Rep file extension (expected .step .stp .iges .igs .brep .brp)");
}

const char* to_string(IFSelect_ReturnStatus status) {
  switch (status) {
    case IFSelect_RetVoid:
      return "void: nothing to read";
    case IFSelect_RetDone:
      return "done";
    case IFSelect_RetError:
      return "error: not a file of this format";
    case IFSelect_RetFail:
      return "fail: could not be read";
    case IFSelect_RetStop:
      return "stop: reading aborted";
  }
  return "unknown";
}

// STEP and IGES: read the file, then transfer every root into one shape.
TopoDS_Shape read_with(XSControl_Reader& reader, const std::filesystem::path& path,
                       const char* format) {
  const IFSelect_ReturnStatus status = reader.ReadFile(path.c_str());
  if (status != IFSelect_RetDone) {
    fail(path, fmt::format("not a readable {} file (OpenCASCADE read status: {})", format,
                           to_string(status)));
  }
  if (reader.TransferRoots() == 0)
    fail(path, fmt::format("no shape could be transferred from the {} file", format));
  return reader.OneShape();
}

// Some of OpenCASCADE's readers write to std::cout directly, past the messenger (BRepTools::Read
// on a file of another version). holebench prints through stdio, never std::cout.
class StdCoutSilenced {
 public:
  StdCoutSilenced() : saved_(std::cout.rdbuf(nullptr)) {}
  ~StdCoutSilenced() { std::cout.rdbuf(saved_); }
  StdCoutSilenced(const StdCoutSilenced&) = delete;
  StdCoutSilenced& operator=(const StdCoutSilenced&) = delete;

 private:
  std::streambuf* saved_;
};

TopoDS_Shape read_any(const std::filesystem::path& path) {
  const StdCoutSilenced silenced;
  switch (format_of(path)) {
    case BrepFormat::Step: {
      STEPControl_Reader reader;
      return read_with(reader, path, "STEP");
    }
    case BrepFormat::Iges: {
      IGESControl_Reader reader;
      return read_with(reader, path, "IGES");
    }
    case BrepFormat::Brep: {
      TopoDS_Shape shape;
      BRep_Builder builder;
      if (!BRepTools::Read(shape, path.c_str(), builder))
        fail(path, "not a readable BREP file (OpenCASCADE's BRepTools::Read failed)");
      return shape;
    }
  }
  return {};
}

}  // namespace

void silence_opencascade_messages() {
  static std::once_flag once;
  std::call_once(once, [] {
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  });
}

TopoDS_Shape read_brep_shape(const std::filesystem::path& path) {
  silence_opencascade_messages();
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    fail(path, "no such file");
  TopoDS_Shape shape;
  try {
    shape = read_any(path);
  } catch (const Standard_Failure& e) {
    fail(path, fmt::format("OpenCASCADE failed reading it ({}: {})", e.DynamicType()->Name(),
                           e.GetMessageString()));
  }
  if (shape.IsNull() || !TopExp_Explorer(shape, TopAbs_FACE).More())
    fail(path, "no faces (the file holds no solid, shell or face)");
  return shape;
}

}  // namespace holebench::occt
