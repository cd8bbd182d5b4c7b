// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * Keeps VTK's warnings and errors for our own report instead of printing them.
 *
 * A reader given a broken file prints several lines of VTK diagnostics (from
 * the reader, its parser and its executive). While a MessageCapture lives,
 * they are kept here, so the program can report the failure in one line that
 * names the scene field, quoting the first thing VTK said.
 *
 * Watching instead (Mode::Watch), VTK still prints every message as it
 * would (through its logger), and the capture only notes them: a render that
 * logged an error can then fail the command.
 */

#ifndef softshadows_MessageCapture_h
#define softshadows_MessageCapture_h

#include <vtkLogger.h>
#include <vtkSmartPointer.h>

#include <string>

class vtkOutputWindow;

namespace softshadows
{
class MessageCapture
{
public:
  enum class Mode
  {
    Keep, ///< messages are kept here, not printed
    Watch ///< printed as VTK prints them, and noted
  };

  explicit MessageCapture(Mode mode = Mode::Keep);
  ~MessageCapture();

  /// Whether VTK posted an error.
  bool HasError() const;

  /// The first line of the first error, as FirstMessage() gives it.
  std::string FirstError() const;

  /// The first line of the first error or warning, without VTK's
  /// "In file, line" and "Class (0x...):" prefixes; empty when none came.
  std::string FirstMessage() const;

  MessageCapture(const MessageCapture&) = delete;
  MessageCapture& operator=(const MessageCapture&) = delete;

private:
  vtkSmartPointer<vtkOutputWindow> Previous;
  vtkSmartPointer<vtkOutputWindow> Capture;
  vtkLogger::Verbosity PreviousVerbosity;
  Mode Kind;
};
}

#endif
