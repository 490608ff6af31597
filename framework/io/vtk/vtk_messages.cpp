#include "framework/io/vtk/vtk_messages.h"

#include <algorithm>
#include <cctype>
#include <vtkLogger.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

#include "framework/util/short_text.h"

namespace subdiv::io_detail {
namespace {

// An output window that keeps the text instead of printing it.
class CollectingWindow : public vtkOutputWindow {
public:
  static CollectingWindow* New();
  vtkTypeMacro(CollectingWindow, vtkOutputWindow);

  void DisplayText(const char* text) override { keep(text, false); }
  void DisplayErrorText(const char* text) override { keep(text, true); }
  void DisplayWarningText(const char* text) override { keep(text, false); }
  void DisplayGenericWarningText(const char* text) override { keep(text, false); }
  void DisplayDebugText(const char*) override {}

  std::string first, first_error;

private:
  void keep(const char* text, bool error) {
    if (!text) return;
    if (first.empty()) first = vtk_readable_message(text);
    if (error && first_error.empty()) first_error = vtk_readable_message(text);
  }
};
vtkStandardNewMacro(CollectingWindow);

}  // namespace

struct VtkMessageCapture::Impl {
  vtkSmartPointer<vtkOutputWindow> previous;
  vtkSmartPointer<CollectingWindow> window = vtkSmartPointer<CollectingWindow>::New();
  vtkLogger::Verbosity previous_stderr = vtkLogger::VERBOSITY_WARNING;
};

VtkMessageCapture::VtkMessageCapture() : impl_(new Impl) {
  impl_->previous = vtkOutputWindow::GetInstance();
  vtkOutputWindow::SetInstance(impl_->window);
  // Some VTK code logs straight to stderr through vtkLogger; silence that too.
  impl_->previous_stderr = vtkLogger::GetCurrentVerbosityCutoff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

VtkMessageCapture::~VtkMessageCapture() {
  vtkOutputWindow::SetInstance(impl_->previous);
  vtkLogger::SetStderrVerbosity(impl_->previous_stderr);
  delete impl_;
}

std::string VtkMessageCapture::first_message() const { return impl_->window->first; }
std::string VtkMessageCapture::first_error() const { return impl_->window->first_error; }

std::string vtk_readable_message(std::string message) {
  if (message.rfind("ERROR: In ", 0) == 0 || message.rfind("Warning: In ", 0) == 0 ||
      message.rfind("Generic Warning: In ", 0) == 0)
    message.erase(0, message.find('\n') + 1);
  // "vtkClass (0x1234): text" -> "text"
  if (const std::size_t object_end = message.find("): "); object_end != std::string::npos &&
                                                          message.rfind("vtk", 0) == 0)
    message.erase(0, object_end + 3);
  // The first line says what went wrong; the rest is dumps (vtkInformation, call stacks).
  if (const std::size_t end = message.find('\n'); end != std::string::npos) message.erase(end);
  while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back()))) message.pop_back();
  return shortened(message, 3 * kQuotedTextChars);
}

}  // namespace subdiv::io_detail
