#include "MessageCapture.h"

#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>

#include <cctype>

namespace softshadows
{
namespace
{
class CapturingWindow : public vtkOutputWindow
{
public:
  static CapturingWindow* New();
  vtkTypeMacro(CapturingWindow, vtkOutputWindow);

  void DisplayText(const char* text) override
  {
    const MessageTypes type = this->GetCurrentMessageType();
    const bool error = type == MESSAGE_TYPE_ERROR;
    const bool warning = type == MESSAGE_TYPE_WARNING || type == MESSAGE_TYPE_GENERIC_WARNING;
    if (text && (error || warning))
    {
      // The first message says what went wrong: a reader's warning that it
      // cannot open the file comes before its executive's error that it failed.
      this->First += this->First.empty() ? Clean(text) : std::string();
      this->HasError = this->HasError || error;
    }
  }

  std::string First;
  bool HasError = false;

private:
  // "ERROR: In file.cxx, line 12\nvtkPLYReader (0x...): What went wrong\n..."
  // becomes "What went wrong".
  static std::string Clean(std::string text)
  {
    const auto header = text.find('\n');
    text = header == std::string::npos ? text : text.substr(header + 1);
    const auto object = text.find("): ");
    text = object == std::string::npos ? text : text.substr(object + 3);
    text = text.substr(0, text.find('\n'));
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
    {
      text.pop_back();
    }
    return text;
  }
};
vtkStandardNewMacro(CapturingWindow);
}

//------------------------------------------------------------------------------
MessageCapture::MessageCapture()
  : Previous(vtkOutputWindow::GetInstance())
  , Capture(vtkSmartPointer<CapturingWindow>::New())
  , PreviousVerbosity(vtkLogger::GetCurrentVerbosityCutoff())
{
  // VTK's macros post both to the logger and to the output window.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkOutputWindow::SetInstance(this->Capture);
}

//------------------------------------------------------------------------------
MessageCapture::~MessageCapture()
{
  vtkOutputWindow::SetInstance(this->Previous);
  vtkLogger::SetStderrVerbosity(this->PreviousVerbosity);
}

//------------------------------------------------------------------------------
bool MessageCapture::HasError() const
{
  return static_cast<CapturingWindow*>(this->Capture.Get())->HasError;
}

//------------------------------------------------------------------------------
std::string MessageCapture::FirstMessage() const
{
  return static_cast<CapturingWindow*>(this->Capture.Get())->First;
}
}
