#include "step/step_file.h"

#include <APIHeaderSection_MakeHeader.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <StepData_StepModel.hxx>
#include <TCollection_HAsciiString.hxx>

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace offsetgen::step {
namespace {

// OpenCASCADE's translators print their statistics on stdout through the default messenger; the
// command prints its own summary.
void silence_translators() {
  static const bool done = [] {
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_Printer));
    return true;
  }();
  (void)done;
}

Handle(TCollection_HAsciiString) text(const std::string& s) { return new TCollection_HAsciiString(s.c_str()); }

}  // namespace

void write_step(const TopoDS_Shape& solid, const std::string& path, const std::string& description, bool pcurves) {
  silence_translators();
  STEPControl_Writer writer;
  Interface_Static::SetCVal("write.step.schema", "AP214IS");
  Interface_Static::SetCVal("write.step.unit", "MM");
  Interface_Static::SetCVal("write.step.product.name", "offsetgen wall");
  Interface_Static::SetIVal("write.surfacecurve.mode", pcurves ? 1 : 0);
  if (writer.Transfer(solid, STEPControl_ManifoldSolidBrep) != IFSelect_RetDone)
    throw std::runtime_error("STEP: the solid could not be translated (STEPControl_Writer::Transfer)");
  // A fixed header: FILE_NAME's time stamp would otherwise be the time of writing.
  APIHeaderSection_MakeHeader header(writer.Model());
  header.SetName(text("offsetgen wall"));
  header.SetTimeStamp(text("2000-01-01T00:00:00"));
  header.SetAuthorValue(1, text(""));
  header.SetOrganizationValue(1, text(""));
  header.SetOriginatingSystem(text(fmt::format("offsetgen {}", OFFSETGEN_VERSION)));
  header.SetAuthorisation(text(""));
  header.SetDescriptionValue(1, text(description));
  if (writer.Write(path.c_str()) != IFSelect_RetDone) throw std::runtime_error("STEP: cannot write " + path);
}

StepContents read_step_contents(const std::string& path) {
  silence_translators();
  STEPControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) throw std::runtime_error("STEP: cannot read " + path);
  StepContents contents;
  APIHeaderSection_MakeHeader header(reader.StepModel());
  if (header.IsDone() && header.NbDescription() > 0 && !header.DescriptionValue(1).IsNull())
    contents.description = header.DescriptionValue(1)->ToCString();
  if (reader.TransferRoots() == 0) throw std::runtime_error("STEP: " + path + " holds no shape");
  contents.shape = reader.OneShape();
  return contents;
}

TopoDS_Shape read_step(const std::string& path) { return read_step_contents(path).shape; }

std::string read_file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace offsetgen::step
