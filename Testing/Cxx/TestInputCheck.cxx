#include "amInputCheck.h"
#include "amTestUtilities.h"

#include <cstdio>
#include <fstream>
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
