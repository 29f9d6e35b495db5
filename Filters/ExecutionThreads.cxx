#include "ExecutionThreads.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <exception>
#include <system_error>

namespace tpc
{
namespace vtkadapter
{
namespace
{
/// Set on a thread while it runs a loop's body: a loop started there runs
/// on it alone.
thread_local bool InLoop = false;

/// The loops of vtkSMPTools as the core asks for them (other backends).
void ForSMP(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body)
{
  const vtkIdType grain = std::max<vtkIdType>(1, static_cast<vtkIdType>(count) / 64);
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), grain,
    [&](vtkIdType begin, vtkIdType end) { body(static_cast<std::size_t>(begin), static_cast<std::size_t>(end)); });
}
} // namespace

/// One loop: its ranges, handed out one by one.
struct ExecutionThreads::Job
{
  const std::function<void(std::size_t, std::size_t)>* Body = nullptr;
  std::size_t Count = 0;
  std::size_t Grain = 1;
  std::size_t Ranges = 0;
  std::atomic<std::size_t> Next{ 0 };
  std::mutex ErrorMutex;
  std::exception_ptr Error; ///< the first exception a range threw
};

ExecutionThreads::ExecutionThreads()
{
  // (Inside a vtkSMPTools loop - the filter run by a threaded pipeline -
  // VTK runs nested loops on their thread unless nested parallelism is on;
  // so do these.)
  if (std::strcmp(vtkSMPTools::GetBackend(), "STDThread") != 0 ||
    (vtkSMPTools::IsParallelScope() && !vtkSMPTools::GetNestedParallelism()))
  {
    return;
  }
  const int threads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  for (int t = 1; t < threads; ++t)
  {
    try
    {
      this->Threads.emplace_back([this] { this->Serve(); });
    }
    catch (const std::system_error&)
    {
      break; // (no more threads to be had: the loops run on those started)
    }
  }
}

ExecutionThreads::~ExecutionThreads()
{
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->Stop = true;
  }
  this->Wake.notify_all();
  for (std::thread& t : this->Threads)
  {
    t.join();
  }
}

ParallelFor ExecutionThreads::Loop()
{
  if (this->Threads.empty())
  {
    return ForSMP; // (another backend, one thread, or a parallel scope: as vtkSMPTools does)
  }
  return [this](std::size_t count, const std::function<void(std::size_t, std::size_t)>& body) {
    this->For(count, body);
  };
}

void ExecutionThreads::Work(Job& job)
{
  const bool outer = InLoop;
  InLoop = true;
  for (;;)
  {
    const std::size_t k = job.Next.fetch_add(1);
    if (k >= job.Ranges)
    {
      break;
    }
    const std::size_t begin = k * job.Grain, end = std::min(job.Count, begin + job.Grain);
    try
    {
      (*job.Body)(begin, end);
    }
    catch (...)
    {
      std::lock_guard<std::mutex> lock(job.ErrorMutex);
      if (!job.Error)
      {
        job.Error = std::current_exception();
      }
      job.Next.store(job.Ranges); // (the other ranges are not started)
    }
  }
  InLoop = outer;
}

void ExecutionThreads::Serve()
{
  unsigned long seen = 0;
  for (;;)
  {
    Job* job = nullptr;
    {
      std::unique_lock<std::mutex> lock(this->Mutex);
      this->Wake.wait(lock, [&] { return this->Stop || this->Posted != seen; });
      if (this->Stop)
      {
        return;
      }
      seen = this->Posted;
      job = this->Current; // (null when the job ended before this thread woke)
      if (!job)
      {
        continue;
      }
      ++this->Inside;
    }
    Work(*job);
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      --this->Inside;
    }
    this->Finished.notify_all();
  }
}

void ExecutionThreads::For(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body)
{
  if (count == 0)
  {
    return;
  }
  bool alone = this->Threads.empty() || count == 1 || InLoop;
  if (!alone)
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    alone = this->Busy; // (another thread's loop holds the threads)
    this->Busy = true;
  }
  if (alone)
  {
    body(0, count);
    return;
  }
  Job job;
  job.Body = &body;
  job.Count = count;
  job.Grain = std::max<std::size_t>(1, count / 64);
  job.Ranges = (count + job.Grain - 1) / job.Grain;
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->Current = &job;
    ++this->Posted;
  }
  this->Wake.notify_all();
  Work(job);
  {
    // Every range is taken; the job lives until no thread is inside it.
    std::unique_lock<std::mutex> lock(this->Mutex);
    this->Finished.wait(lock, [&] { return this->Inside == 0; });
    this->Current = nullptr;
    this->Busy = false;
  }
  if (job.Error)
  {
    std::rethrow_exception(job.Error);
  }
}

} // namespace vtkadapter
} // namespace tpc
