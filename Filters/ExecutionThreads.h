// Adapter: the core's parallel loops (Parallel.h) on VTK's threads.
//
// With vtkSMPTools' STDThread backend, VTK 9.2 starts and joins its threads
// in every vtkSMPTools::For: about 0.15-0.25 ms a loop on a 2-core machine,
// and a run makes some 300 loops (each level of the subdivision, each pass
// of the extraction, each round of a parallel sort) - a tenth to a fifth of
// a mesh's run at 1/64 went to starting threads. (VTK 9.3 keeps a pool; 9.2
// is the VTK ParaView 5.11 ships.) So for that backend the threads are
// started once per execution of the filter and handed every loop; with any
// other backend (Sequential; TBB or OpenMP, which keep their own workers)
// the loops go to vtkSMPTools::For as they are, as they do inside a
// vtkSMPTools loop (a threaded pipeline) unless nested parallelism is on. Hand-written rather than a
// library's pool: the number of threads and the backend stay VTK's
// (vtkSMPTools::Initialize, VTK_SMP_MAX_THREADS, VTK_SMP_BACKEND_IN_USE),
// and the filter takes no new dependency.
#ifndef ExecutionThreads_h
#define ExecutionThreads_h

#include "Parallel.h"

#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace tpc
{
namespace vtkadapter
{

class ExecutionThreads
{
public:
  /// Starts vtkSMPTools::GetEstimatedNumberOfThreads() - 1 threads when the
  /// backend is STDThread (none otherwise, or as many as the system gives).
  ExecutionThreads();
  /// Joins them.
  ~ExecutionThreads();
  ExecutionThreads(const ExecutionThreads&) = delete;
  ExecutionThreads& operator=(const ExecutionThreads&) = delete;

  /// The core's ParallelFor on these threads: body(begin, end) over about
  /// 64 ranges covering [0, count), taken in turn by the calling thread and
  /// the others; returns when all are done (an exception thrown by body is
  /// thrown again here, the ranges not yet started skipped). A loop started
  /// from inside a loop's body, or while another thread runs one, runs on the
  /// calling thread alone. Without threads of its own: vtkSMPTools::For.
  ParallelFor Loop();

private:
  struct Job;
  void For(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body);
  void Serve();
  static void Work(Job& job);

  std::vector<std::thread> Threads;
  std::mutex Mutex;
  std::condition_variable Wake;     ///< a job was posted, or Stop
  std::condition_variable Finished; ///< a thread left a job
  Job* Current = nullptr;           ///< (guarded by Mutex)
  unsigned long Posted = 0;         ///< jobs posted so far (guarded by Mutex)
  std::size_t Inside = 0;           ///< threads working on Current (guarded by Mutex)
  bool Busy = false;                ///< a loop is running (guarded by Mutex)
  bool Stop = false;                ///< (guarded by Mutex)
};

} // namespace vtkadapter
} // namespace tpc

#endif
