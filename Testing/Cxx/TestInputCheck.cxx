#include "amInputCheck.h"
#include "amTestUtilities.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkShortArray.h"

#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

TEST(InputCheck, ReadableFileRefusesWhatWouldBlockAReader)
{
  const std::string file = amTest::TempPath("input_check_file.txt");
  {
    std::ofstream(file) << "x";
  }
  const std::string fifo = amTest::TempPath("input_check_fifo");
  std::remove(fifo.c_str());
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string loop = amTest::TempPath("input_check_loop");
  std::remove(loop.c_str());
  ASSERT_EQ(::symlink(loop.c_str(), loop.c_str()), 0);
  std::string why;
  EXPECT_TRUE(amInputCheck::ReadableFile(file, false, why)) << why;
  EXPECT_FALSE(amInputCheck::ReadableFile(fifo, true, why));
  EXPECT_EQ(why, "'" + fifo + "' is a FIFO (named pipe), not a regular file.");
  EXPECT_FALSE(amInputCheck::ReadableFile(loop, true, why));
  EXPECT_EQ(why, "'" + loop + "' is a symbolic link loop.");
  EXPECT_FALSE(amInputCheck::ReadableFile(file + ".missing", true, why));
  EXPECT_EQ(why, "'" + file + ".missing' does not exist.");
  EXPECT_FALSE(amInputCheck::ReadableFile("/dev/null", false, why));
  EXPECT_EQ(why, "'/dev/null' is a device, not a regular file.");
  const std::string folder = amTest::TempPath("");
  EXPECT_TRUE(amInputCheck::ReadableFile(folder, true, why)) << why;
  EXPECT_FALSE(amInputCheck::ReadableFile(folder, false, why));
  std::remove(fifo.c_str());
  std::remove(loop.c_str());
}

TEST(InputCheck, LabelCountRefusesAScan)
{
  std::string why;
  EXPECT_TRUE(amInputCheck::LabelCount(amInputCheck::MaximumLabels, why));
  EXPECT_FALSE(amInputCheck::LabelCount(amInputCheck::MaximumLabels + 1, why));
  EXPECT_NE(why.find("1001 distinct values"), std::string::npos) << why;
  EXPECT_NE(why.find("is this the scan"), std::string::npos) << why;
}

TEST(InputCheck, LabelCountsAreOneCheckForEveryType)
{
  // 300 000 voxels (five blocks of the threads' 65 536), labels in runs and alone, negative too.
  const vtkIdType n = 300000;
  vtkNew<vtkShortArray> shorts;
  shorts->SetNumberOfTuples(n);
  std::map<int, vtkIdType> truth;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const short v = static_cast<short>(i < 1000 ? -3 : (i / 7000) % 11);
    shorts->SetValue(i, v);
    ++truth[v];
  }
  std::map<int, vtkIdType> counts;
  std::string why;
  ASSERT_TRUE(amInputCheck::LabelCounts(shorts, -amInputCheck::LargestLabel, amInputCheck::LargestLabel, counts, why));
  EXPECT_EQ(counts, truth);
  // The same through the generic path (an array that is not a plain buffer of one component).
  vtkNew<vtkDoubleArray> pairs;
  pairs->SetNumberOfComponents(2);
  pairs->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
    pairs->SetComponent(i, 0, shorts->GetValue(i));
  ASSERT_TRUE(amInputCheck::LabelCounts(pairs, -10, 10, counts, why)) << why;
  EXPECT_EQ(counts, truth);
  // The first offender is named, whichever block finds one first.
  vtkNew<vtkFloatArray> floats;
  floats->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
    floats->SetValue(i, i == 250000 || i == 200001 ? 0.5f : 2.0f);
  EXPECT_FALSE(amInputCheck::LabelCounts(floats, -amInputCheck::LargestLabel, amInputCheck::LargestLabel, counts, why));
  EXPECT_EQ(why,
    "Voxel 200001 has value 0.5: a label map holds whole numbers -2e+09..2e+09 (this float array looks like an "
    "intensity image).");
  floats->SetValue(200001, std::numeric_limits<float>::quiet_NaN());
  floats->SetValue(250000, 2.0f);
  EXPECT_FALSE(amInputCheck::LabelCounts(floats, 0, 255, counts, why));
  EXPECT_NE(why.find("Voxel 200001 has value nan"), std::string::npos) << why;
  floats->SetValue(200001, 256.0f);
  EXPECT_FALSE(amInputCheck::LabelCounts(floats, 0, 255, counts, why));
  EXPECT_NE(why.find("whole numbers 0..255"), std::string::npos) << why;
}
