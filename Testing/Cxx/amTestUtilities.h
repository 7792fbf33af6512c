// Shared helpers of the GoogleTest suites: capture VTK errors, find the shared scans.
#ifndef amTestUtilities_h
#define amTestUtilities_h

#include "vtkCommand.h"
#include "vtkObject.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <string>
#include <sys/stat.h>
#include <vector>

namespace amTest
{
/// Records the text of every ErrorEvent/WarningEvent of the objects it observes (and keeps VTK
/// from printing them), so a test can assert that bad input gave a clear message.
class ErrorCatcher : public vtkCommand
{
public:
  static ErrorCatcher* New() { return new ErrorCatcher; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings).push_back(text);
  }
  void Watch(vtkObject* o)
  {
    o->AddObserver(vtkCommand::ErrorEvent, this);
    o->AddObserver(vtkCommand::WarningEvent, this);
  }
  bool HasError() const { return !this->Errors.empty(); }
  std::string AllErrors() const
  {
    std::string all;
    for (const auto& e : this->Errors)
      all += e + "\n";
    return all;
  }
  bool ErrorContains(const std::string& needle) const { return this->AllErrors().find(needle) != std::string::npos; }
  std::vector<std::string> Errors, Warnings;
};

inline bool Exists(const std::string& path)
{
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

/// Path of a file in ../shared/data, or "" (the test should GTEST_SKIP) if it is absent.
inline std::string SharedData(const std::string& relative)
{
  const std::string path = std::string(ANATOMESH_SHARED_DATA) + "/" + relative;
  return Exists(path) ? path : std::string();
}

/// The frog's tissue label map (15 organs) in ../shared/data.
constexpr const char* FrogLabels = "vtk_frog_tissue_labels/frogtissue.mhd";

inline std::string TempPath(const std::string& name)
{
  return std::string(ANATOMESH_TEST_TMP) + "/" + name;
}
}

#define AM_REQUIRE_SHARED(var, relative)                                                                               \
  const std::string var = amTest::SharedData(relative);                                                                \
  if (var.empty())                                                                                                     \
  GTEST_SKIP() << "shared data '" << relative << "' is absent (expected in " ANATOMESH_SHARED_DATA ")"

#endif
