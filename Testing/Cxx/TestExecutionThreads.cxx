// The core's parallel loops on threads started once per execution
// (ExecutionThreads.h): every index of a loop is visited exactly once, from
// more than one thread, loops started inside a loop run on their caller, an
// exception reaches the caller, and the filter's output is the same, bit for
// bit, on one thread (the Sequential backend) and on two.
#include "ExecutionThreads.h"
#include "FilterTestHelpers.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkSphereSource.h"
#include "vtkTriangleFilter.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace
{
/// The given SMP backend with 2 threads (as many as the machine has, if
/// fewer) while it lives; then the backend and number the tests run with.
class Backend
{
public:
  explicit Backend(const char* backend)
    : Before(vtkSMPTools::GetBackend())
    , Threads(vtkSMPTools::GetEstimatedNumberOfThreads())
  {
    this->Set = vtkSMPTools::SetBackend(backend);
    vtkSMPTools::Initialize(2);
  }
  ~Backend()
  {
    vtkSMPTools::SetBackend(this->Before.c_str());
    vtkSMPTools::Initialize(this->Threads);
  }
  bool Set = false;

private:
  std::string Before;
  int Threads;
};

/// Runs `test` with the backend (Backend).
template <typename Test>
void WithBackend(const char* backend, const Test& test)
{
  const Backend scope(backend);
  ASSERT_TRUE(scope.Set) << backend;
  test();
}
} // namespace

TEST(ExecutionThreads, EveryIndexOnceFromTwoThreads)
{
  WithBackend("STDThread", [] {
    if (vtkSMPTools::GetEstimatedNumberOfThreads() < 2)
    {
      GTEST_SKIP() << "one processor: no thread to start";
    }
    tpc::vtkadapter::ExecutionThreads threads;
    const tpc::ParallelFor loop = threads.Loop();
    for (const std::size_t count : { std::size_t(0), std::size_t(1), std::size_t(5), std::size_t(64),
           std::size_t(1000), std::size_t(100003) })
    {
      std::vector<std::atomic<int>> visits(count);
      std::mutex mutex;
      std::condition_variable arrived;
      bool waitedInVain = false;
      std::set<std::thread::id> seen;
      loop(count, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
        {
          ++visits[i];
        }
        std::unique_lock<std::mutex> lock(mutex);
        seen.insert(std::this_thread::get_id());
        if (count >= 1000 && !waitedInVain)
        {
          // Each range waits (3 s at most, once) until the other thread has
          // taken one: with a thread that never takes work, the caller does
          // them all, alone.
          arrived.notify_all();
          waitedInVain = !arrived.wait_for(lock, std::chrono::seconds(3), [&] { return seen.size() >= 2; });
        }
      });
      for (std::size_t i = 0; i < count; ++i)
      {
        ASSERT_EQ(visits[i].load(), 1) << "index " << i << " of " << count;
      }
      if (count >= 1000)
      {
        EXPECT_EQ(seen.size(), 2u) << count; // the caller and the one thread started
      }
    }
  });
}

TEST(ExecutionThreads, NestedLoopsAndExceptions)
{
  WithBackend("STDThread", [] {
    tpc::vtkadapter::ExecutionThreads threads;
    const tpc::ParallelFor loop = threads.Loop();
    // A loop inside a loop's body runs on the thread that started it.
    std::atomic<long> total{ 0 };
    loop(64, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
      {
        const std::thread::id outer = std::this_thread::get_id();
        loop(100, [&](std::size_t b, std::size_t e) {
          EXPECT_EQ(std::this_thread::get_id(), outer);
          total += static_cast<long>(e - b);
        });
      }
    });
    EXPECT_EQ(total.load(), 6400);
    // An exception thrown in a range reaches the caller; the threads stay
    // usable.
    EXPECT_THROW(loop(1000, [](std::size_t begin, std::size_t) {
      if (begin >= 500)
      {
        throw std::runtime_error("range failed");
      }
    }), std::runtime_error);
    std::atomic<std::size_t> after{ 0 };
    loop(1000, [&](std::size_t begin, std::size_t end) { after += end - begin; });
    EXPECT_EQ(after.load(), 1000u);
  });
}

TEST(ExecutionThreads, FilterOutputIsTheSameOnOneThreadAndTwo)
{
  // A sphere mesh remeshed at 1/64, as extracted and decimated: the core's
  // loops write only their own ranges (Parallel.h), and the decimation's
  // batches decide as one after another (CertifiedDecimation.h, Parallel),
  // so the threads change nothing.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(32);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(sphere->GetOutputPort());
  triangles->Update();
  for (const bool decimate : { false, true })
  {
    std::vector<double> points[2];
    std::vector<vtkIdType> cells[2];
    const char* backends[2] = { "Sequential", "STDThread" };
    for (int k = 0; k < 2; ++k)
    {
      WithBackend(backends[k], [&] {
        if (k == 1 && vtkSMPTools::GetEstimatedNumberOfThreads() < 2)
        {
          GTEST_SKIP() << "one processor: one thread either way";
        }
        vtkNew<vtkTopologyPreservingContour> filter;
        filter->SetInputData(triangles->GetOutput());
        filter->SetTolerance(1.0 / 64);
        filter->SetDecimate(decimate);
        const tpctest::FilterResult r = tpctest::Run(filter);
        EXPECT_EQ(r.Guaranteed, 1) << backends[k];
        vtkDataArray* xyz = r.Surface->GetPoints()->GetData();
        for (vtkIdType i = 0; i < xyz->GetNumberOfValues(); ++i)
        {
          points[k].push_back(xyz->GetComponent(i / 3, static_cast<int>(i % 3)));
        }
        vtkDataArray* connectivity = r.Surface->GetPolys()->GetConnectivityArray();
        for (vtkIdType i = 0; i < connectivity->GetNumberOfValues(); ++i)
        {
          cells[k].push_back(static_cast<vtkIdType>(connectivity->GetComponent(i, 0)));
        }
      });
    }
    EXPECT_GT(cells[0].size(), decimate ? 30u : 100u) << decimate;
    EXPECT_EQ(points[0], points[1]) << decimate;
    EXPECT_EQ(cells[0], cells[1]) << decimate;
  }
}
