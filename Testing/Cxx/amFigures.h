#pragma once
// The README's figures, recorded by the tests that check them: with ANATOMESH_FIGURES set to a file,
// RecordFigure appends one JSON line (the running test's name, the figure's name, value, unit and the
// bar the test holds it to); scripts/figures.py runs those tests and gathers the lines into
// docs/figures.json. Without the variable it does nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace amTest
{
inline void RecordFigure(const std::string& name, double value, const std::string& unit, double bar = NAN)
{
  const char* path = std::getenv("ANATOMESH_FIGURES");
  if (!path || !*path)
    return;
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string test = info ? std::string(info->test_suite_name()) + "." + info->name() : "";
  std::FILE* f = std::fopen(path, "a");
  if (!f)
    return;
  std::string barText = std::isfinite(bar) ? std::to_string(bar) : "null";
  std::fprintf(f, "{\"test\": \"%s\", \"name\": \"%s\", \"value\": %.10g, \"unit\": \"%s\", \"bar\": %s}\n",
    test.c_str(), name.c_str(), value, unit.c_str(), barText.c_str());
  std::fclose(f);
}
}
