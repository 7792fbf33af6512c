// NIfTI files that ITK would read wrongly or crash on: each refused with a message naming the file
// and the problem, before any voxel is allocated. The files are the reader's own outputs, cut or
// with one header field changed.
#include "amImageReader.h"
#include "amImageWriter.h"
#include "amTestUtilities.h"
#include "amThoraxPhantomSource.h"

#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkNew.h"

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <vector>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
std::vector<char> Bytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void Save(const std::string& path, const std::vector<char>& bytes)
{
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

template<typename T>
void Put(std::vector<char>& bytes, size_t offset, T value)
{
  std::memcpy(bytes.data() + offset, &value, sizeof(T));
}

/// The 8 mm phantom's CT written by amImageWriter as NAME.nii or NAME.nii.gz (each test its own
/// files: ctest runs the tests in parallel).
std::string Written(const std::string& name, bool compressed)
{
  vtkNew<amThoraxPhantomSource> src;
  src->SetSpacing(8, 8, 8);
  vtkNew<amImageWriter> writer;
  writer->SetInputConnection(src->GetOutputPort(0));
  const std::string path = amTest::TempPath(name + (compressed ? ".nii.gz" : ".nii"));
  writer->SetFileName(path.c_str());
  EXPECT_EQ(writer->Write(), 1);
  return path;
}

/// Reads 'path' and expects a refusal whose message names the file and holds every needle.
void ExpectRefused(const std::string& path, const std::vector<std::string>& needles)
{
  vtkNew<amImageReader> reader;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(reader);
  errors->Watch(reader->GetExecutive());
  reader->SetFileName(path.c_str());
  const auto start = std::chrono::steady_clock::now();
  reader->Update();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(errors->HasError()) << path << " was read";
  EXPECT_TRUE(errors->ErrorContains(path)) << errors->AllErrors();
  for (const auto& n : needles)
    EXPECT_TRUE(errors->ErrorContains(n)) << "'" << n << "' not in: " << errors->AllErrors();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0) << path;
  EXPECT_LT(seconds, 5.0) << path; // refused before allocating what the header asks
}
}

TEST(NiftiCheck, TheWriterOwnFilesRead)
{
  for (bool compressed : { false, true })
  {
    vtkNew<amImageReader> reader;
    vtkNew<amTest::ErrorCatcher> errors;
    errors->Watch(reader);
    reader->SetFileName(Written("nifti_written", compressed).c_str());
    reader->Update();
    EXPECT_FALSE(errors->HasError()) << errors->AllErrors();
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 40 * 30 * 26);
  }
}

TEST(NiftiCheck, TruncatedOrCorruptCompressedStreams)
{
  const std::vector<char> gz = Bytes(Written("nifti_streams", true));
  const std::string half = amTest::TempPath("cut_half.nii.gz"), early = amTest::TempPath("cut_1000.nii.gz"),
                    crc = amTest::TempPath("bad_crc.nii.gz"), corrupt = amTest::TempPath("bad_deflate.nii.gz");
  Save(half, std::vector<char>(gz.begin(), gz.begin() + gz.size() / 2));
  Save(early, std::vector<char>(gz.begin(), gz.begin() + 1000));
  std::vector<char> b = gz;
  b[b.size() - 6] ^= 0x7f; // in the CRC-32 of the gzip trailer
  Save(crc, b);
  b = gz;
  for (size_t i = b.size() / 2; i < b.size() / 2 + 40; ++i)
    b[i] ^= 0x5a;
  Save(corrupt, b);
  ExpectRefused(half, { "truncated" });
  ExpectRefused(early, { "truncated" });
  ExpectRefused(crc, { "corrupt" });
  ExpectRefused(corrupt, { "corrupt" });
}

TEST(NiftiCheck, TruncatedDataAbsurdSizesAndOffsets)
{
  const std::vector<char> raw = Bytes(Written("nifti_sizes", false));
  const std::string half = amTest::TempPath("cut_half.nii"), huge = amTest::TempPath("huge.nii"),
                    offset = amTest::TempPath("offset.nii");
  Save(half, std::vector<char>(raw.begin(), raw.begin() + raw.size() / 2));
  std::vector<char> b(raw.begin(), raw.begin() + 65536);
  Put<int16_t>(b, 42, 1000); // 1000^3 voxels announced over 64 kB
  Put<int16_t>(b, 44, 1000);
  Put<int16_t>(b, 46, 1000);
  Save(huge, b);
  b = raw;
  Put<float>(b, 108, static_cast<float>(raw.size() + 1000)); // vox_offset past the end
  Save(offset, b);
  ExpectRefused(half, { "truncated" });
  ExpectRefused(huge, { "truncated", "2000000000 bytes" });
  ExpectRefused(offset, { "past its end" });
}

TEST(NiftiCheck, NonFiniteOrDegenerateGeometry)
{
  const std::vector<char> raw = Bytes(Written("nifti_geometry", false));
  struct Case
  {
    const char* Name;
    std::function<void(std::vector<char>&)> Change;
    const char* Needle;
  };
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const std::vector<Case> cases = {
    { "sform_nan.nii", [&](std::vector<char>& b) { Put<float>(b, 280, nan); }, "srow_x" }, // ITK aborted here
    { "sform_flat.nii",
      [&](std::vector<char>& b) {
        for (int c = 0; c < 4; ++c)
          Put<float>(b, 312 + 4 * c, 0.0f);
      },
      "degenerate" },
    { "qform_inf.nii", [&](std::vector<char>& b) { Put<float>(b, 256, inf); }, "quatern_b" },
    { "qform_long.nii",
      [&](std::vector<char>& b) {
        Put<float>(b, 256, 0.9f);
        Put<float>(b, 260, 0.9f);
      },
      "not a rotation" },
    { "spacing_zero.nii", [&](std::vector<char>& b) { Put<float>(b, 80, 0.0f); }, "pixdim[1]" },
    { "spacing_nan.nii", [&](std::vector<char>& b) { Put<float>(b, 84, nan); }, "pixdim[2]" },
    { "rank_zero.nii", [&](std::vector<char>& b) { Put<int16_t>(b, 40, 0); }, "dim[0]" },
    { "negative_dim.nii", [&](std::vector<char>& b) { Put<int16_t>(b, 44, -3); }, "dim[2] = -3" },
    { "no_magic.nii", [&](std::vector<char>& b) { std::memcpy(b.data() + 344, "xyz", 4); }, "magic" },
  };
  for (const Case& c : cases)
  {
    std::vector<char> b = raw;
    c.Change(b);
    const std::string path = amTest::TempPath(c.Name);
    Save(path, b);
    ExpectRefused(path, { c.Needle });
  }
}

TEST(NiftiCheck, ShortWriteLeavesTheOldFileAndNoTemporary)
{
  // A file size limit (as a full disk would) cuts the write short; ITK may not say so. The writer
  // must fail, keep the valid file already at the target, and leave no temporary file.
  const std::string target = Written("nifti_short_write", false);
  const std::vector<char> before = Bytes(target);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0)
  {
    ::signal(SIGXFSZ, SIG_IGN); // writes past the limit fail with EFBIG instead of killing
    struct rlimit limit = { 20000, 20000 };
    ::setrlimit(RLIMIT_FSIZE, &limit);
    vtkNew<amThoraxPhantomSource> src;
    src->SetSpacing(4, 4, 4); // 0.5 MB of voxels
    vtkNew<amImageWriter> writer;
    vtkNew<amTest::ErrorCatcher> errors;
    errors->Watch(writer);
    errors->Watch(writer->GetExecutive());
    writer->SetInputConnection(src->GetOutputPort(0));
    writer->SetFileName(target.c_str());
    const int ok = writer->Write();
    ::_exit(ok == 0 && errors->ErrorContains("incomplete") ? 0 : 1);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the writer did not fail with 'incomplete'";
  EXPECT_EQ(Bytes(target), before); // the old file untouched
  const std::string folder = target.substr(0, target.find_last_of('/'));
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    EXPECT_EQ(entry.path().filename().string().find(".nifti_short_write.tmp"), std::string::npos)
      << entry.path() << " left behind";
}
