#include "amAtomicFile.h"
#include "amTestUtilities.h"

#include <cstdio>
#include <fstream>

TEST(AtomicFile, Extensions)
{
  EXPECT_EQ(amAtomicFile::Extension("/a/b/img.nii.gz"), ".nii.gz");
  EXPECT_EQ(amAtomicFile::Extension("x.MHA"), ".mha");
  EXPECT_EQ(amAtomicFile::Extension("/a.b/noext"), "");
}

TEST(AtomicFile, CommitOrNothing)
{
  const std::string target = amTest::TempPath("atomic.mesh");
  std::remove(target.c_str());
  std::string tmp;
  {
    amAtomicFile f(target);
    tmp = f.TemporaryPath();
    EXPECT_EQ(amAtomicFile::Extension(tmp), ".mesh");
    std::ofstream(tmp) << "half";
    // no Commit: an error happened
  }
  EXPECT_FALSE(amTest::Exists(tmp));
  EXPECT_FALSE(amTest::Exists(target));
  {
    amAtomicFile f(target);
    std::ofstream(f.TemporaryPath()) << "whole";
    std::string why;
    ASSERT_TRUE(f.Commit(why)) << why;
  }
  std::ifstream in(target);
  std::string text;
  in >> text;
  EXPECT_EQ(text, "whole");
}

TEST(AtomicFile, RefusesMissingFolder)
{
  amAtomicFile f("/nonexistent-folder-xyz/out.nii");
  std::string why;
  EXPECT_FALSE(f.CanWrite(why));
  EXPECT_NE(why.find("does not exist"), std::string::npos);
}
