// amConcurrentXMLWriter: a series of frames written on worker threads, byte for byte what one
// vtkXML*Writer writes, whatever the thread count; the data copied when queued; a folder that does
// not exist and a type with no format are errors naming the file, with no file left behind.
#include "amConcurrentXMLWriter.h"
#include "amTestUtilities.h"

#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkTable.h"
#include "vtkXMLImageDataWriter.h"
#include "vtkXMLPolyDataWriter.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
std::string Read(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool Exists(const std::string& path)
{
  return std::ifstream(path).good();
}

/// Frame k: a sphere whose point data "Potential" depends on k.
vtkSmartPointer<vtkPolyData> Frame(int k)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(40);
  sphere->Update();
  auto frame = vtkSmartPointer<vtkPolyData>::New();
  frame->DeepCopy(sphere->GetOutput());
  vtkNew<vtkDoubleArray> potential;
  potential->SetName("Potential");
  potential->SetNumberOfTuples(frame->GetNumberOfPoints());
  for (vtkIdType i = 0; i < frame->GetNumberOfPoints(); ++i)
    potential->SetValue(i, std::sin(0.1 * i + k));
  frame->GetPointData()->AddArray(potential);
  return frame;
}

std::string Name(const char* stem, int k)
{
  return amTest::TempPath(std::string(stem) + "_" + std::to_string(k) + ".vtp");
}
}

TEST(ConcurrentXMLWriter, FramesAreThoseOfOneWriterWhateverTheThreads)
{
  const int frames = 12;
  for (int k = 0; k < frames; ++k)
  {
    vtkNew<vtkXMLPolyDataWriter> plain;
    plain->SetInputData(Frame(k));
    plain->SetFileName(Name("plain", k).c_str());
    plain->SetDataModeToBinary();
    plain->SetCompressorTypeToZLib();
    plain->SetCompressionLevel(1);
    ASSERT_TRUE(plain->Write());
  }
  for (int threads : { 1, 3 })
  {
    vtkNew<amConcurrentXMLWriter> files;
    files->SetNumberOfThreads(threads);
    for (int k = 0; k < frames; ++k)
    {
      vtkSmartPointer<vtkPolyData> frame = Frame(k);
      ASSERT_TRUE(files->Write(frame, Name("queued", k).c_str())) << files->GetErrorMessage();
      // The queue holds a copy: changing the frame now changes nothing written.
      frame->GetPointData()->GetArray("Potential")->Fill(0.0);
    }
    ASSERT_TRUE(files->Finish()) << files->GetErrorMessage();
    EXPECT_STREQ(files->GetErrorMessage(), "");
    for (int k = 0; k < frames; ++k)
    {
      const std::string expected = Read(Name("plain", k));
      ASSERT_GT(expected.size(), 1000u);
      EXPECT_EQ(Read(Name("queued", k)), expected) << "frame " << k << ", " << threads << " threads";
    }
  }
}

TEST(ConcurrentXMLWriter, AnImageToo)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(30, 20, 10);
  image->AllocateScalars(VTK_FLOAT, 1);
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
    image->GetPointData()->GetScalars()->SetTuple1(i, 0.5 * i);
  vtkNew<vtkXMLImageDataWriter> plain;
  plain->SetInputData(image);
  const std::string expectedPath = amTest::TempPath("plain_image.vti"), path = amTest::TempPath("queued_image.vti");
  plain->SetFileName(expectedPath.c_str());
  plain->SetDataModeToBinary();
  plain->SetCompressorTypeToZLib();
  plain->SetCompressionLevel(1);
  ASSERT_TRUE(plain->Write());
  vtkNew<amConcurrentXMLWriter> files;
  ASSERT_TRUE(files->Write(image, path.c_str()));
  ASSERT_TRUE(files->Finish());
  EXPECT_EQ(Read(path), Read(expectedPath));
}

TEST(ConcurrentXMLWriter, FailuresNameTheFileAndLeaveNone)
{
  const std::string missing = amTest::TempPath("no_such_folder/frame.vtp");
  const std::string after = amTest::TempPath("after_the_failure.vtp");
  std::remove(after.c_str());
  vtkNew<amConcurrentXMLWriter> files;
  ASSERT_TRUE(files->Write(Frame(0), missing.c_str()));
  EXPECT_FALSE(files->Finish());
  const std::string message = files->GetErrorMessage();
  std::printf("%s\n", message.c_str());
  EXPECT_EQ(message.rfind(missing + ": ", 0), 0u) << message;
  EXPECT_FALSE(Exists(missing));
  // Nothing more is written after a failure.
  EXPECT_FALSE(files->Write(Frame(1), after.c_str()));
  files->Finish();
  EXPECT_FALSE(Exists(after));

  vtkNew<amConcurrentXMLWriter> tables;
  vtkNew<vtkTable> table;
  const std::string csv = amTest::TempPath("table.vtp");
  EXPECT_FALSE(tables->Write(table, csv.c_str()));
  EXPECT_NE(std::string(tables->GetErrorMessage()).find("no VTK XML format for a vtkTable"), std::string::npos)
    << tables->GetErrorMessage();
  EXPECT_FALSE(tables->Finish());
  EXPECT_FALSE(Exists(csv));
}
