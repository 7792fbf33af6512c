#include "amAtomicFile.h"
#include "amTestUtilities.h"

#include <csignal>
#include <cstdio>
#include <fstream>
#include <string>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

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

TEST(AtomicFile, TheNextWriterRemovesTheTemporariesOfKilledRuns)
{
  // A run killed mid-write leaves ".<stem>.tmp<pid>_<n><ext>"; the next writer of the same target
  // removes it when that process is gone, and leaves those of running processes and other targets.
  const pid_t dead = fork();
  if (dead == 0)
    _exit(0);
  ASSERT_GT(dead, 0);
  waitpid(dead, nullptr, 0); // reaped: the PID no longer runs
  const std::string target = amTest::TempPath("stale.nii.gz");
  const std::string stale = amTest::TempPath(".stale.tmp" + std::to_string(dead) + "_0.nii.gz");
  const std::string live = amTest::TempPath(".stale.tmp1_0.nii.gz"); // PID 1 always runs
  const std::string other = amTest::TempPath(".other.tmp" + std::to_string(dead) + "_0.nii.gz");
  for (const auto& path : { stale, live, other })
    std::ofstream(path) << "half";
  {
    amAtomicFile f(target);
  }
  EXPECT_FALSE(amTest::Exists(stale));
  EXPECT_TRUE(amTest::Exists(live));
  EXPECT_TRUE(amTest::Exists(other));
  std::remove(live.c_str());
  std::remove(other.c_str());
}

TEST(AtomicFile, CheckedWritesKeepTheOldFileUnderASizeLimit)
{
  const std::string target = amTest::TempPath("atomic_limit.bin");
  {
    std::ofstream(target) << "old";
  }
  // In a child process: the file size limit is the process's own.
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0)
  {
    signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{ 1000, 1000 };
    setrlimit(RLIMIT_FSIZE, &limit);
    amAtomicFile f(target);
    std::string why;
    const bool wrote = f.WriteTemporary(std::string(5000, 'x'), why);
    _exit(!wrote && why == "File too large" ? 0 : 1);
  }
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  std::ifstream in(target);
  std::string text;
  in >> text;
  EXPECT_EQ(text, "old");
  // Without a limit: written, checked, committed.
  amAtomicFile f(target);
  std::string why;
  ASSERT_TRUE(f.WriteTemporary(std::string(5000, 'y'), why)) << why;
  ASSERT_TRUE(f.Commit(why)) << why;
  struct stat st;
  ASSERT_EQ(::stat(target.c_str(), &st), 0);
  EXPECT_EQ(st.st_size, 5000);
}
