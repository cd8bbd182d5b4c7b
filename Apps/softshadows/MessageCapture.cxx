// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "MessageCapture.h"

#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>

#include <cctype>
#include <iostream>

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
      this->FirstError += error && this->FirstError.empty() ? Clean(text) : std::string();
      this->HasError = this->HasError || error;
    }
    // Watching: VTK's logger has printed it already, unless VTK was built
    // without one, when its own window would print it.
    if (text && this->Print && !vtkLogger::IsEnabled())
    {
      std::cerr << text;
    }
  }

  std::string First;
  std::string FirstError;
  bool HasError = false;
  bool Print = false;

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
MessageCapture::MessageCapture(Mode mode)
  : Previous(vtkOutputWindow::GetInstance())
  , Capture(vtkSmartPointer<CapturingWindow>::New())
  , PreviousVerbosity(vtkLogger::GetCurrentVerbosityCutoff())
  , Kind(mode)
{
  // VTK's macros post both to the logger and to the output window.
  if (mode == Mode::Keep)
  {
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  static_cast<CapturingWindow*>(this->Capture.Get())->Print = mode == Mode::Watch;
  vtkOutputWindow::SetInstance(this->Capture);
}

//------------------------------------------------------------------------------
MessageCapture::~MessageCapture()
{
  vtkOutputWindow::SetInstance(this->Previous);
  if (this->Kind == Mode::Keep)
  {
    vtkLogger::SetStderrVerbosity(this->PreviousVerbosity);
  }
}

//------------------------------------------------------------------------------
bool MessageCapture::HasError() const
{
  return static_cast<CapturingWindow*>(this->Capture.Get())->HasError;
}

//------------------------------------------------------------------------------
std::string MessageCapture::FirstError() const
{
  return static_cast<CapturingWindow*>(this->Capture.Get())->FirstError;
}

//------------------------------------------------------------------------------
std::string MessageCapture::FirstMessage() const
{
  return static_cast<CapturingWindow*>(this->Capture.Get())->First;
}
}
