// libFuzzer target: the pipeline-XML parser and validator (Python, pipeline_target.py) on any
// bytes, in an embedded interpreter. libFuzzer's coverage comes from the Python code: a trace
// function counts the (previous line, line) pairs executed in 8-bit counters registered with
// libFuzzer as an extra module, as atheris does. An exception other than PipelineError aborts
// with its traceback, so the fuzzer keeps the input.
#include <Python.h>
#include <frameobject.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>

#ifndef ANATOMESH_SOURCE_DIR
#error "ANATOMESH_SOURCE_DIR must name the source tree"
#endif

extern "C" void __sanitizer_cov_8bit_counters_init(uint8_t* start, uint8_t* stop);
extern "C" void __sanitizer_cov_pcs_init(const uintptr_t* begin, const uintptr_t* end);

namespace
{
constexpr size_t Counters = 1 << 16;
alignas(64) uint8_t counters[Counters];
uintptr_t pcs[2 * Counters]; // (pseudo program counter, flags) per counter
uint32_t previous = 0;
PyObject* check = nullptr;

int Trace(PyObject*, PyFrameObject* frame, int what, PyObject*)
{
  if (what != PyTrace_LINE && what != PyTrace_CALL)
    return 0;
  PyCodeObject* code = PyFrame_GetCode(frame);
  const uint32_t here = static_cast<uint32_t>(reinterpret_cast<uintptr_t>(code) >> 4) * 2654435761u ^
    static_cast<uint32_t>(PyFrame_GetLineNumber(frame)) * 40503u;
  Py_DECREF(code);
  uint8_t& counter = counters[(here ^ previous) % Counters];
  if (counter < 255)
    ++counter;
  previous = here >> 1;
  return 0;
}

void Fail(const char* what)
{
  if (PyErr_Occurred())
    PyErr_Print();
  std::fprintf(stderr, "FuzzPipelineXml: %s\n", what);
  std::abort();
}
}

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  for (size_t i = 0; i < Counters; ++i)
    pcs[2 * i] = i + 1;
  __sanitizer_cov_8bit_counters_init(counters, counters + Counters);
  __sanitizer_cov_pcs_init(pcs, pcs + 2 * Counters);
  Py_Initialize();
  PyObject* sys = PyImport_ImportModule("sys");
  PyObject* path = sys ? PyObject_GetAttrString(sys, "path") : nullptr;
  PyObject* here = PyUnicode_FromString(ANATOMESH_SOURCE_DIR "/Testing/Fuzz");
  if (!path || !here || PyList_Insert(path, 0, here) != 0)
    Fail("cannot set sys.path");
  PyObject* target = PyImport_ImportModule("pipeline_target");
  PyObject* setup = target ? PyObject_GetAttrString(target, "setup") : nullptr;
  check = target ? PyObject_GetAttrString(target, "check") : nullptr;
  if (!setup || !check || !PyObject_CallFunction(setup, "s", ANATOMESH_SOURCE_DIR))
    Fail("cannot load pipeline_target.py");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  PyObject* bytes = PyBytes_FromStringAndSize(reinterpret_cast<const char*>(data), static_cast<Py_ssize_t>(size));
  previous = 0;
  PyEval_SetTrace(Trace, nullptr);
  PyObject* result = PyObject_CallOneArg(check, bytes);
  PyEval_SetTrace(nullptr, nullptr);
  Py_DECREF(bytes);
  if (!result)
    Fail("the validator raised an exception other than PipelineError (traceback above)");
  Py_DECREF(result);
  return 0;
}
