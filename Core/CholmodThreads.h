// CholmodThreads.h: the threads CHOLMOD's calls run on, for as long as a CholmodThreads lives:
// the BLAS under CHOLMOD on one thread, and CHOLMOD's own OpenMP loops on the cores the load
// leaves.
//
// BLAS. CHOLMOD's supernodal factorization factors each supernode's diagonal block with LAPACK's
// potrf and updates the rest with the BLAS (syrk, gemm, trsm); its solves call trsv/gemv or
// trsm/gemm. OpenBLAS's own potrf splits its work by the thread count, and the factor's last bits
// change with it (OpenBLAS 0.3.21: from 64 rows on with 2 threads against 1; syrk, gemm, trsm and
// gemv gave the same bits), and from there the singularities, the map and the quads. With one
// thread for the length of each CHOLMOD call the results are the same for every
// OPENBLAS_NUM_THREADS. The solves are held to one thread too: it costs nothing, and no OpenBLAS
// version then has to sum in a fixed order across threads. On two cores the second thread saved
// nothing measurable (Documentation/Development.md).
//
// OpenMP. Debian's CHOLMOD (SuiteSparse 5.12) asks for a parallel loop of a fixed 4 threads
// (CHOLMOD_OMP_NUM_THREADS, a num_threads clause that OMP_NUM_THREADS does not lower) for each
// supernode with more than 128 rows to clear or scatter; on 2 cores its threads waited on each
// other at every supernode, and armadillo's map took 0.6 s to factor instead of 0.25 s
// (Benchmarks/README.md). With OpenMP's dynamic adjustment on in the calling thread, the runtime
// may give a loop fewer threads (libgomp: the cores less the load average, at most
// OMP_NUM_THREADS). Each loop sets independent rows, so the result does not depend on how many
// threads it gets.
//
// OpenBLAS and OpenMP are found at run time, so that the code runs unchanged with the reference
// BLAS (single threaded: nothing to do), another BLAS (left as it is) or a CHOLMOD without
// OpenMP. They are looked up among the libraries CHOLMOD itself was loaded with, which also
// works when Python loads our module with RTLD_LOCAL (they are then not in the global scope).
#ifndef quadcover_CholmodThreads_h
#define quadcover_CholmodThreads_h

#include <mutex>

#if defined(QUADCOVER_HAVE_CHOLMOD) && defined(__unix__)
#include <cholmod.h>
#include <dlfcn.h>
#define QUADCOVER_CHOLMOD_THREADS_DLSYM 1
#endif

namespace quadcover
{
namespace detail
{
struct CholmodThreadControl
{
  using SetThreads = void (*)(int);
  using GetThreads = int (*)();
  SetThreads set = nullptr;  ///< openblas_set_num_threads
  GetThreads get = nullptr;  ///< openblas_get_num_threads
  SetThreads setDynamic = nullptr; ///< omp_set_dynamic
  GetThreads getDynamic = nullptr; ///< omp_get_dynamic
  std::mutex mutex;
  int depth = 0; ///< CholmodThreads objects alive (several threads may factor at once)
  int saved = 1; ///< the thread count to restore when the last one ends

  CholmodThreadControl()
  {
#ifdef QUADCOVER_CHOLMOD_THREADS_DLSYM
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
    if (!this->set || !this->setDynamic)
    {
      this->find(RTLD_DEFAULT);
    }
#endif
  }

#ifdef QUADCOVER_CHOLMOD_THREADS_DLSYM
  void find(void* handle)
  {
    lookUp(handle, "openblas_set_num_threads", "openblas_get_num_threads", this->set, this->get);
    lookUp(handle, "omp_set_dynamic", "omp_get_dynamic", this->setDynamic, this->getDynamic);
  }

  /// The pair of functions named, unless found before; both or neither.
  static void lookUp(
    void* handle, const char* setName, const char* getName, SetThreads& set, GetThreads& get)
  {
    if (set && get)
    {
      return;
    }
    set = reinterpret_cast<SetThreads>(dlsym(handle, setName));
    get = reinterpret_cast<GetThreads>(dlsym(handle, getName));
    if (!set || !get)
    {
      set = nullptr;
      get = nullptr;
    }
  }
#endif

  static CholmodThreadControl& instance()
  {
    static CholmodThreadControl control;
    return control;
  }
};
}

/// While alive, OpenBLAS (when it is the BLAS) runs on one thread, and the OpenMP loops the
/// calling thread opens (CHOLMOD's) get the threads the runtime's dynamic adjustment allows. The
/// BLAS thread count from before comes back when the last such object, of any thread, ends; the
/// calling thread's dynamic adjustment when this one ends.
class CholmodThreads
{
public:
  CholmodThreads()
  {
    detail::CholmodThreadControl& c = detail::CholmodThreadControl::instance();
    if (c.setDynamic)
    {
      // the ICV is the calling thread's own: no other thread sees it
      this->dynamic = c.getDynamic();
      if (!this->dynamic)
      {
        c.setDynamic(1);
      }
    }
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

  ~CholmodThreads()
  {
    detail::CholmodThreadControl& c = detail::CholmodThreadControl::instance();
    if (c.setDynamic && !this->dynamic)
    {
      c.setDynamic(0);
    }
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

  CholmodThreads(const CholmodThreads&) = delete;
  CholmodThreads& operator=(const CholmodThreads&) = delete;

  /// Whether OpenBLAS was found (else the BLAS is left as it is).
  static bool controlsBlas() { return detail::CholmodThreadControl::instance().set != nullptr; }
  /// Whether OpenMP was found (else CHOLMOD's loops are left as they are).
  static bool controlsOpenMP()
  {
    return detail::CholmodThreadControl::instance().setDynamic != nullptr;
  }

private:
  int dynamic = 1; ///< the calling thread's dynamic adjustment before
};
}

#endif
