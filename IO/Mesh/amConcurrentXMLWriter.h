/**
 * @class   amConcurrentXMLWriter
 * @brief   Writes VTK XML files (.vtu, .vtp, .vti), and runs queued writers, on worker threads
 *          while the caller goes on.
 *
 * Write() queues a deep copy of the data and returns at once; the workers compress and write the
 * queued files, each through a temporary file beside its target renamed when complete (no reader
 * ever sees half a file). A time series of a hundred frames is written in about 1/NumberOfThreads
 * of one writer's time, and files queued before a long filter runs are written while it runs.
 * The files are those of vtkXMLUnstructuredGridWriter, vtkXMLPolyDataWriter and
 * vtkXMLImageDataWriter with inline binary (base64) data compressed by zlib at CompressionLevel:
 * the same bytes whatever the number of threads and whichever thread wrote them.
 *
 * Errors (a folder that cannot be written, a full disk, a type with no such format) are kept, not
 * reported from the worker threads: Finish() returns false and GetErrorMessage() names the first
 * file that failed and why. That file's temporary is removed and nothing queued after the failure
 * is written. The destructor waits for the queued files too.
 */
#ifndef amConcurrentXMLWriter_h
#define amConcurrentXMLWriter_h

#include "AnatomeshIOMeshModule.h" // export macro
#include "vtkObject.h"

class vtkAlgorithm;
class vtkDataObject;

class ANATOMESHIOMESH_EXPORT amConcurrentXMLWriter : public vtkObject
{
public:
  static amConcurrentXMLWriter* New();
  vtkTypeMacro(amConcurrentXMLWriter, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Worker threads (default 2), taken at the first Write after construction or Finish().
  vtkSetClampMacro(NumberOfThreads, int, 1, 64);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// zlib compression level, 1 (fastest, default) to 9 (smallest).
  vtkSetClampMacro(CompressionLevel, int, 1, 9);
  vtkGetMacro(CompressionLevel, int);
  ///@}

  /// Queues a copy of 'data' to be written to 'fileName' in the VTK XML format of its type
  /// (vtkUnstructuredGrid: .vtu, vtkPolyData: .vtp, vtkImageData: .vti). Waits while
  /// 2 x NumberOfThreads files are queued. False, queuing nothing, when the data has none of
  /// those types or a file already failed.
  bool Write(vtkDataObject* data, const char* fileName);

  /// Queues a writer that writes its input when it executes (amImageWriter, amMeditWriter,
  /// amGmshWriter, amOpenCARPWriter), to execute on a worker thread: each connected input is replaced
  /// by a deep copy of the data it has now (update the inputs first), so the caller may go on with
  /// the pipeline. The
  /// writer must have no observers that need the calling thread (Python callbacks): remove them
  /// first. Its first error fails the queue as a file's would (GetErrorMessage() then names
  /// 'fileName'); its warnings are kept (GetWarning()). Queues above the 2 x NumberOfThreads of
  /// Write() without waiting: a writer is queued once, not frame after frame. False, queuing
  /// nothing, when it has no input data or a file already failed.
  bool QueueWriter(vtkAlgorithm* writer, const char* fileName);

  /// The warnings of the queued writers so far: "<file>: <message>" (VTK's text, with its file,
  /// line and class). Read them after Finish(): a writer still running may add one.
  int GetNumberOfWarnings();
  const char* GetWarning(int i);

  /// Waits until every queued file is written. False when one failed (see GetErrorMessage()).
  bool Finish();

  /// "<file>: <why>" for the first file that failed; empty while none did.
  const char* GetErrorMessage();

protected:
  amConcurrentXMLWriter();
  ~amConcurrentXMLWriter() override;

private:
  amConcurrentXMLWriter(const amConcurrentXMLWriter&) = delete;
  void operator=(const amConcurrentXMLWriter&) = delete;

  void StartWorkers(); // with the queue's lock held

  struct Internal;
  Internal* Impl;
  int NumberOfThreads;
  int CompressionLevel;
};

#endif
