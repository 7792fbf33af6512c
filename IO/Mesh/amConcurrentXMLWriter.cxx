#include "amConcurrentXMLWriter.h"

#include "amAtomicFile.h"
#include "amBase64OutputStream.h"
#include "amCachedZLibCompressor.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkErrorCode.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLImageDataWriter.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

vtkStandardNewMacro(amConcurrentXMLWriter);

namespace
{
struct Job
{
  vtkSmartPointer<vtkDataObject> Data;
  vtkSmartPointer<vtkAlgorithm> Writer; // or a writer to execute, its input a copy of its own
  std::string File;
};

/// Whether the data has a VTK XML format here.
bool Writable(vtkDataObject* data)
{
  return vtkUnstructuredGrid::SafeDownCast(data) || vtkPolyData::SafeDownCast(data) || vtkImageData::SafeDownCast(data);
}

/// A deep copy of the data, the worker's own.
vtkSmartPointer<vtkDataObject> CopyOf(vtkDataObject* data)
{
  vtkSmartPointer<vtkDataObject> copy;
  copy.TakeReference(data->NewInstance());
  copy->DeepCopy(data);
  return copy;
}

/// VTK's XML writer W with amBase64OutputStream for its inline data (the same file, written in
/// blocks rather than four characters at a time).
template<typename W>
class BlockBase64 : public W
{
public:
  static BlockBase64* New()
  {
    auto* writer = new BlockBase64;
    writer->InitializeObjectBase();
    return writer;
  }

protected:
  BlockBase64()
  {
    vtkNew<amBase64OutputStream> stream;
    this->SetDataStream(stream);
  }
};

/// A writer for the data's type, or null.
vtkSmartPointer<vtkXMLWriter> WriterFor(vtkDataObject* data)
{
  if (vtkUnstructuredGrid::SafeDownCast(data))
    return vtkSmartPointer<BlockBase64<vtkXMLUnstructuredGridWriter>>::New();
  if (vtkPolyData::SafeDownCast(data))
    return vtkSmartPointer<BlockBase64<vtkXMLPolyDataWriter>>::New();
  if (vtkImageData::SafeDownCast(data))
    return vtkSmartPointer<BlockBase64<vtkXMLImageDataWriter>>::New();
  return nullptr;
}

/// The writer's error messages, caught by an observer: VTK then does not print them from a
/// worker thread (where a Python output window may not run).
void KeepMessage(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* message = static_cast<std::string*>(clientData);
  if (message->empty() && callData)
    *message = static_cast<const char*>(callData);
}

/// Each warning, caught the same way.
void KeepWarning(vtkObject*, unsigned long, void* clientData, void* callData)
{
  if (callData)
    static_cast<std::vector<std::string>*>(clientData)->emplace_back(static_cast<const char*>(callData));
}

/// The text after VTK's "ERROR: In file, line N" line and "class (0x...): " prefix, whole (its own
/// lines and colons kept: a library's message quoted in it).
std::string Body(const std::string& message)
{
  std::size_t start = 0;
  if (message.compare(0, 10, "ERROR: In ") == 0 || message.compare(0, 12, "Warning: In ") == 0)
  {
    const std::size_t eol = message.find('\n');
    start = eol == std::string::npos ? 0 : eol + 1;
  }
  const std::size_t colon = message.find("): ", start);
  const std::size_t eol = message.find('\n', start);
  if (colon != std::string::npos && (eol == std::string::npos || colon < eol))
    start = colon + 3;
  std::string body = message.substr(start);
  while (!body.empty() && (body.back() == '\n' || body.back() == ' '))
    body.pop_back();
  return body;
}

/// Executes a queued writer; an empty string, or why it failed. Its warnings are appended.
std::string RunWriter(const Job& job, std::vector<std::string>& warnings)
{
  std::string message;
  vtkNew<vtkCallbackCommand> keep, warn;
  keep->SetCallback(KeepMessage);
  keep->SetClientData(&message);
  warn->SetCallback(KeepWarning);
  warn->SetClientData(&warnings);
  vtkAlgorithm* writer = job.Writer;
  const unsigned long errorTag = writer->AddObserver(vtkCommand::ErrorEvent, keep);
  const unsigned long warningTag = writer->AddObserver(vtkCommand::WarningEvent, warn);
  const unsigned long executiveTag = writer->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, keep);
  writer->Modified();
  const int ok = writer->GetExecutive()->Update();
  writer->GetExecutive()->RemoveObserver(executiveTag);
  writer->RemoveObserver(warningTag);
  writer->RemoveObserver(errorTag);
  if (!message.empty())
    return Body(message);
  return ok ? std::string() : std::string("the writer reported no success");
}

/// Writes one file; an empty string, or why it failed.
std::string WriteOne(const Job& job, int level, std::vector<std::string>& warnings,
  const std::shared_ptr<amCachedZLibCompressor::Cache>& blocks)
{
  if (job.Writer)
    return RunWriter(job, warnings);
  amAtomicFile file(job.File);
  std::string why;
  if (!file.CanWrite(why))
    return why;
  vtkSmartPointer<vtkXMLWriter> writer = WriterFor(job.Data);
  std::string message;
  vtkNew<vtkCallbackCommand> keep;
  keep->SetCallback(KeepMessage);
  keep->SetClientData(&message);
  writer->AddObserver(vtkCommand::ErrorEvent, keep);
  writer->AddObserver(vtkCommand::WarningEvent, keep);
  writer->SetInputData(job.Data);
  // Into memory, then to the disk with checked system calls: VTK 9.2's XML writers free unallocated
  // arrays when a write to a file fails part-way (a full disk, a file size limit).
  writer->WriteToOutputStringOn();
  // Inline base64 ("binary"), not appended: Debian 12's expat (2.5.0+deb12u5, with the backported
  // reparse deferral) breaks VTK 9.2's reading of appended data beyond a few kB.
  writer->SetDataModeToBinary();
  // zlib, each block deflated once in the queue's life (a series' frames share their geometry).
  vtkNew<amCachedZLibCompressor> compressor;
  compressor->SetCache(blocks);
  writer->SetCompressor(compressor);
  writer->SetCompressionLevel(level);
  const int ok = writer->Write();
  const unsigned long code = writer->GetErrorCode();
  if (!ok || code != vtkErrorCode::NoError)
  {
    if (code != vtkErrorCode::NoError)
      return vtkErrorCode::GetStringFromErrorCode(code);
    return message.empty() ? "the VTK XML writer failed" : Body(message);
  }
  if (!file.WriteTemporary(writer->GetOutputString(), why))
    return why;
  if (!file.Commit(why))
    return why;
  return std::string();
}
}

struct amConcurrentXMLWriter::Internal
{
  std::mutex Lock;
  std::condition_variable Changed;
  std::deque<Job> Queue;
  std::vector<std::thread> Workers;
  std::size_t Busy = 0; // jobs taken and not yet done
  bool Stopping = false;
  int Level = 1;
  std::string Error;
  std::vector<std::string> Warnings;
  std::shared_ptr<amCachedZLibCompressor::Cache> Blocks = amCachedZLibCompressor::NewCache();

  void Work()
  {
    for (;;)
    {
      Job job;
      {
        std::unique_lock<std::mutex> lock(this->Lock);
        this->Changed.wait(lock, [this]() { return !this->Queue.empty() || this->Stopping; });
        if (this->Queue.empty())
          return;
        job = std::move(this->Queue.front());
        this->Queue.pop_front();
        ++this->Busy;
      }
      std::vector<std::string> warnings;
      const std::string why = WriteOne(job, this->Level, warnings, this->Blocks);
      job.Data = nullptr; // released on this thread, before the caller may wait for an empty queue
      job.Writer = nullptr;
      std::lock_guard<std::mutex> lock(this->Lock);
      for (const std::string& w : warnings)
        this->Warnings.push_back(job.File + ": " + w);
      if (!why.empty() && this->Error.empty())
      {
        this->Error = job.File + ": " + why;
        this->Queue.clear(); // nothing more is written after a failure
      }
      --this->Busy;
      this->Changed.notify_all();
    }
  }

  void Stop()
  {
    {
      std::lock_guard<std::mutex> lock(this->Lock);
      this->Stopping = true;
    }
    this->Changed.notify_all();
    for (std::thread& t : this->Workers)
      t.join();
    this->Workers.clear();
    this->Stopping = false;
  }
};

amConcurrentXMLWriter::amConcurrentXMLWriter()
  : Impl(new Internal)
  , NumberOfThreads(2)
  , CompressionLevel(1)
{
}

amConcurrentXMLWriter::~amConcurrentXMLWriter()
{
  this->Impl->Stop();
  delete this->Impl;
}

bool amConcurrentXMLWriter::Write(vtkDataObject* data, const char* fileName)
{
  Internal& in = *this->Impl;
  if (!data || !fileName || !*fileName || !Writable(data))
  {
    std::lock_guard<std::mutex> lock(in.Lock);
    if (in.Error.empty())
      in.Error = std::string(fileName ? fileName : "(no file name)") + ": no VTK XML format for a " +
        (data ? data->GetClassName() : "missing data object");
    return false;
  }
  Job job;
  job.Data = CopyOf(data);
  job.File = fileName;
  std::unique_lock<std::mutex> lock(in.Lock);
  if (!in.Error.empty())
    return false;
  this->StartWorkers();
  const std::size_t most = 2 * static_cast<std::size_t>(this->NumberOfThreads);
  in.Changed.wait(lock, [&]() { return in.Queue.size() < most || !in.Error.empty(); });
  if (!in.Error.empty())
    return false;
  in.Queue.push_back(std::move(job));
  in.Changed.notify_all();
  return true;
}

void amConcurrentXMLWriter::StartWorkers()
{
  Internal& in = *this->Impl;
  if (!in.Workers.empty())
    return;
  in.Level = this->CompressionLevel;
  for (int t = 0; t < this->NumberOfThreads; ++t)
    in.Workers.emplace_back([&in]() { in.Work(); });
}

bool amConcurrentXMLWriter::QueueWriter(vtkAlgorithm* writer, const char* fileName)
{
  Internal& in = *this->Impl;
  const std::string file = fileName && *fileName ? fileName : "(no file name)";
  // Every connected input (the mesh; an optional second one such as openCARP's surfaces) is copied:
  // the worker then touches no pipeline.
  std::vector<vtkSmartPointer<vtkDataObject>> copies;
  bool ok = writer && writer->GetNumberOfInputPorts() >= 1 && writer->GetNumberOfInputConnections(0) == 1;
  for (int port = 0; ok && port < writer->GetNumberOfInputPorts(); ++port)
  {
    const int connections = writer->GetNumberOfInputConnections(port);
    vtkDataObject* data = connections == 1 ? writer->GetInputDataObject(port, 0) : nullptr;
    ok = connections == 0 ? port > 0 : data != nullptr;
    copies.push_back(data ? CopyOf(data) : nullptr);
  }
  if (!ok)
  {
    std::lock_guard<std::mutex> lock(in.Lock);
    if (in.Error.empty())
      in.Error = file + ": " + (writer ? "the writer has no input data of one connection" : "no writer");
    return false;
  }
  Job job;
  job.Writer = writer;
  job.File = file;
  std::unique_lock<std::mutex> lock(in.Lock);
  if (!in.Error.empty())
    return false;
  for (std::size_t port = 0; port < copies.size(); ++port)
    if (copies[port])
      writer->SetInputDataObject(static_cast<int>(port), copies[port]);
  this->StartWorkers();
  in.Queue.push_back(std::move(job));
  in.Changed.notify_all();
  return true;
}

int amConcurrentXMLWriter::GetNumberOfWarnings()
{
  std::lock_guard<std::mutex> lock(this->Impl->Lock);
  return static_cast<int>(this->Impl->Warnings.size());
}

const char* amConcurrentXMLWriter::GetWarning(int i)
{
  std::lock_guard<std::mutex> lock(this->Impl->Lock);
  return i >= 0 && i < static_cast<int>(this->Impl->Warnings.size()) ? this->Impl->Warnings[i].c_str() : "";
}

bool amConcurrentXMLWriter::Finish()
{
  Internal& in = *this->Impl;
  {
    std::unique_lock<std::mutex> lock(in.Lock);
    in.Changed.wait(lock, [&]() { return in.Queue.empty() && in.Busy == 0; });
  }
  in.Stop();
  std::lock_guard<std::mutex> lock(in.Lock);
  return in.Error.empty();
}

const char* amConcurrentXMLWriter::GetErrorMessage()
{
  std::lock_guard<std::mutex> lock(this->Impl->Lock);
  return this->Impl->Error.c_str();
}

void amConcurrentXMLWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "CompressionLevel: " << this->CompressionLevel << "\n";
}
