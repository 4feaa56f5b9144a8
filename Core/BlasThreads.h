// BlasThreads.h: runs the BLAS under CHOLMOD on one thread for as long as a OneBlasThread lives.
//
// CHOLMOD's supernodal factorization factors each supernode's diagonal block with LAPACK's potrf
// and updates the rest with the BLAS (syrk, gemm, trsm); its solves call trsv/gemv or trsm/gemm.
// OpenBLAS's own potrf splits its work by the thread count, and the factor's last bits change
// with it (OpenBLAS 0.3.21: from 64 rows on with 2 threads against 1; syrk, gemm, trsm and gemv
// gave the same bits), and from there the singularities, the map and the quads. With one thread
// for the length of each CHOLMOD call the results are the same for every OPENBLAS_NUM_THREADS.
// The solves are held to one thread too: it costs nothing, and no OpenBLAS version then has to
// sum in a fixed order across threads. On two cores the second thread saved nothing measurable
// (Documentation/Development.md).
//
// OpenBLAS is found at run time, so that the code runs unchanged with the reference BLAS (single
// threaded: nothing to do) or another BLAS (left as it is). It is looked up among the libraries
// CHOLMOD itself was loaded with, which also works when Python loads our module with RTLD_LOCAL
// (the BLAS is then not in the global scope).
#ifndef quadcover_BlasThreads_h
#define quadcover_BlasThreads_h

#include <mutex>

#if defined(QUADCOVER_HAVE_CHOLMOD) && defined(__unix__)
#include <cholmod.h>
#include <dlfcn.h>
#define QUADCOVER_BLAS_THREADS_DLSYM 1
#endif

namespace quadcover
{
namespace detail
{
struct BlasThreadControl
{
  using SetThreads = void (*)(int);
  using GetThreads = int (*)();
  SetThreads set = nullptr;
  GetThreads get = nullptr;
  std::mutex mutex;
  int depth = 0; ///< OneBlasThread objects alive (several threads may factor at once)
  int saved = 1; ///< the thread count to restore when the last one ends

  BlasThreadControl()
  {
#ifdef QUADCOVER_BLAS_THREADS_DLSYM
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&cholmod_start), &info) && info.dli_fname)
    {
      // NOLOAD: the library is loaded (we call it); a handle searches it and its dependencies.
      if (void* cholmod = dlopen(info.dli_fname, RTLD_LAZY | RTLD_NOLOAD))
      {
        this->find(cholmod);
        dlclose(cholmod); // still loaded: our own library needs it
      }
    }
    if (!this->set || !this->get)
    {
      this->find(RTLD_DEFAULT);
    }
#endif
  }

#ifdef QUADCOVER_BLAS_THREADS_DLSYM
  void find(void* handle)
  {
    this->set = reinterpret_cast<SetThreads>(dlsym(handle, "openblas_set_num_threads"));
    this->get = reinterpret_cast<GetThreads>(dlsym(handle, "openblas_get_num_threads"));
    if (!this->set || !this->get)
    {
      this->set = nullptr;
      this->get = nullptr;
    }
  }
#endif

  static BlasThreadControl& instance()
  {
    static BlasThreadControl control;
    return control;
  }
};
}

/// While alive, OpenBLAS (when it is the BLAS) runs on one thread; the thread count from before
/// comes back when the last such object, of any thread, ends.
class OneBlasThread
{
public:
  OneBlasThread()
  {
    detail::BlasThreadControl& c = detail::BlasThreadControl::instance();
    if (!c.set)
    {
      return;
    }
    std::lock_guard<std::mutex> lock(c.mutex);
    if (c.depth++ == 0)
    {
      c.saved = c.get();
      if (c.saved != 1)
      {
        c.set(1);
      }
    }
  }

  ~OneBlasThread()
  {
    detail::BlasThreadControl& c = detail::BlasThreadControl::instance();
    if (!c.set)
    {
      return;
    }
    std::lock_guard<std::mutex> lock(c.mutex);
    if (--c.depth == 0 && c.saved != 1)
    {
      c.set(c.saved);
    }
  }

  OneBlasThread(const OneBlasThread&) = delete;
  OneBlasThread& operator=(const OneBlasThread&) = delete;

  /// Whether OpenBLAS was found (else the object does nothing).
  static bool controlsBlas() { return detail::BlasThreadControl::instance().set != nullptr; }
};
}

#endif
