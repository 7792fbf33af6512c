// amConcurrentXMLWriter: a series of frames written on worker threads, byte for byte what one
// vtkXML*Writer writes, whatever the thread count; the data copied when queued; a folder that does
// not exist and a type with no format are errors naming the file, with no file left behind; a
// queued writer writes the bytes it writes alone, its warnings and errors kept with its file.
#include "amBase64OutputStream.h"
#include "amCachedZLibCompressor.h"
#include "amConcurrentXMLWriter.h"
#include "amGmshWriter.h"
#include "amMeditWriter.h"
#include "amTestUtilities.h"

#include "vtkBase64OutputStream.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLImageDataWriter.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtkZLibDataCompressor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
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

namespace
{
/// Two tetrahedra sharing a face, regions 1 and 2.
vtkSmartPointer<vtkUnstructuredGrid> TwoTetrahedra()
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  for (const auto& p : { std::array<double, 3>{ 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 1 } })
    points->InsertNextPoint(p.data());
  grid->SetPoints(points);
  const vtkIdType a[4] = { 0, 1, 2, 3 }, b[4] = { 1, 2, 3, 4 };
  grid->InsertNextCell(VTK_TETRA, 4, a);
  grid->InsertNextCell(VTK_TETRA, 4, b);
  vtkNew<vtkIntArray> region;
  region->SetName("Region");
  region->InsertNextValue(1);
  region->InsertNextValue(2);
  grid->GetCellData()->AddArray(region);
  return grid;
}
}

TEST(ConcurrentXMLWriter, QueuedWritersWriteWhatTheyWouldHaveWritten)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = TwoTetrahedra();
  const std::string direct = amTest::TempPath("direct.mesh"), queued = amTest::TempPath("queued.mesh");
  vtkNew<amMeditWriter> one;
  one->SetInputData(grid);
  one->SetFileName(direct.c_str());
  ASSERT_EQ(one->Write(), 1);

  vtkNew<amConcurrentXMLWriter> files;
  vtkNew<amMeditWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(queued.c_str());
  ASSERT_TRUE(files->QueueWriter(writer, queued.c_str()));
  // The data was copied when queued: a change now is not written.
  grid->GetPoints()->SetPoint(4, 2, 2, 2);
  ASSERT_TRUE(files->Finish()) << files->GetErrorMessage();
  EXPECT_EQ(Read(queued), Read(direct));
  EXPECT_EQ(files->GetNumberOfWarnings(), 0);

  // A writer's warning is kept with its file; its error fails the queue, naming the file.
  vtkNew<amConcurrentXMLWriter> more;
  grid->GetCellData()->GetArray("Region")->SetComponent(1, 0, 1234);
  const std::string warned = amTest::TempPath("warned.msh"), missing = amTest::TempPath("no_such_folder/x.msh");
  vtkNew<amGmshWriter> gmsh, broken;
  gmsh->SetInputData(grid);
  gmsh->SetFileName(warned.c_str());
  broken->SetInputData(grid);
  broken->SetFileName(missing.c_str());
  ASSERT_TRUE(more->QueueWriter(gmsh, warned.c_str()));
  ASSERT_TRUE(more->Finish());
  ASSERT_EQ(more->GetNumberOfWarnings(), 1);
  EXPECT_EQ(std::string(more->GetWarning(0)).rfind(warned + ": ", 0), 0u) << more->GetWarning(0);
  EXPECT_STREQ(more->GetWarning(1), "");
  EXPECT_TRUE(Exists(warned));
  ASSERT_TRUE(more->QueueWriter(broken, missing.c_str()));
  EXPECT_FALSE(more->Finish());
  EXPECT_EQ(std::string(more->GetErrorMessage()).rfind(missing + ": ", 0), 0u) << more->GetErrorMessage();
  EXPECT_FALSE(Exists(missing));

  // A writer without input is refused.
  vtkNew<amConcurrentXMLWriter> none;
  vtkNew<amMeditWriter> empty;
  EXPECT_FALSE(none->QueueWriter(empty, "empty.mesh"));
  EXPECT_NE(std::string(none->GetErrorMessage()).find("no input"), std::string::npos) << none->GetErrorMessage();
}

// The cached compressor: VTK's zlib bytes, the second time from its cache (a changed block is
// compressed anew, not mistaken for the cached one), under VTK's zlib class name.
TEST(ConcurrentXMLWriter, CachedBlocksAreZLibsBytes)
{
  std::vector<unsigned char> block(32768);
  for (size_t i = 0; i < block.size(); ++i)
    block[i] = static_cast<unsigned char>((i * 7919u) >> 5);
  vtkNew<vtkZLibDataCompressor> plain;
  plain->SetCompressionLevel(1);
  vtkSmartPointer<vtkUnsignedCharArray> expected;
  expected.TakeReference(plain->Compress(block.data(), block.size()));
  auto cache = amCachedZLibCompressor::NewCache();
  vtkNew<amCachedZLibCompressor> first, second;
  first->SetCache(cache);
  second->SetCache(cache);
  first->SetCompressionLevel(1);
  second->SetCompressionLevel(1);
  EXPECT_STREQ(second->GetClassName(), "vtkZLibDataCompressor");
  auto same = [&](vtkUnsignedCharArray* a, vtkUnsignedCharArray* b) {
    return a->GetNumberOfValues() == b->GetNumberOfValues() &&
      std::equal(a->GetPointer(0), a->GetPointer(0) + a->GetNumberOfValues(), b->GetPointer(0));
  };
  for (vtkDataCompressor* c : { static_cast<vtkDataCompressor*>(first), static_cast<vtkDataCompressor*>(second) })
  {
    vtkSmartPointer<vtkUnsignedCharArray> got;
    got.TakeReference(c->Compress(block.data(), block.size()));
    EXPECT_TRUE(same(got, expected));
  }
  block[100] ^= 0xFF; // the same hash bucket is not enough: the bytes are compared
  expected.TakeReference(plain->Compress(block.data(), block.size()));
  vtkSmartPointer<vtkUnsignedCharArray> changed;
  changed.TakeReference(second->Compress(block.data(), block.size()));
  EXPECT_TRUE(same(changed, expected));
  // Another level is another entry.
  second->SetCompressionLevel(9);
  plain->SetCompressionLevel(9);
  expected.TakeReference(plain->Compress(block.data(), block.size()));
  changed.TakeReference(second->Compress(block.data(), block.size()));
  EXPECT_TRUE(same(changed, expected));
}

TEST(Base64OutputStream, TheBytesOfVTKsStreamWhateverTheWrites)
{
  // Every length up to 70 kB boundaries' neighbours, cut into writes of every size pattern:
  // block encoding, triplets split across writes and both paddings give VTK's bytes.
  std::vector<unsigned char> data(3 * (1 << 14) + 7);
  for (size_t i = 0; i < data.size(); ++i)
    data[i] = static_cast<unsigned char>((i * 131 + (i >> 8) * 7) & 0xff);
  const std::vector<size_t> lengths = { 0, 1, 2, 3, 4, 5, 6, 7, 3 * (1 << 14) - 1, 3 * (1 << 14), data.size() };
  const std::vector<size_t> pieces = { 1, 2, 4, 5, 1000, data.size() };
  for (size_t length : lengths)
    for (size_t piece : pieces)
    {
      std::ostringstream expected, got;
      vtkNew<vtkBase64OutputStream> reference;
      vtkNew<amBase64OutputStream> stream;
      reference->SetStream(&expected);
      stream->SetStream(&got);
      ASSERT_TRUE(reference->StartWriting() && stream->StartWriting());
      for (size_t at = 0; at < length; at += piece)
      {
        const size_t n = std::min(piece, length - at);
        ASSERT_TRUE(reference->Write(data.data() + at, n));
        ASSERT_TRUE(stream->Write(data.data() + at, n));
      }
      ASSERT_TRUE(reference->EndWriting() && stream->EndWriting());
      EXPECT_EQ(got.str(), expected.str()) << length << " bytes in writes of " << piece;
      EXPECT_EQ(got.str().size(), (length + 2) / 3 * 4);
    }
}
