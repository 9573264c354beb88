// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/solver/sparse_cholesky.h"

#include <cholmod.h>
#include <dlfcn.h>
#include <omp.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <mutex>
#include <string>
#include <type_traits>

#include "core/errors.h"

namespace meshfair {

static_assert(std::is_same_v<SuiteSparse_long, std::int64_t> ||
                  sizeof(SuiteSparse_long) == sizeof(std::int64_t),
              "CHOLMOD's long indices are read in place as int64_t");

void SymmetricMatrix::multiply(std::span<const Scalar> x, std::span<Scalar> y) const
{
    std::fill(y.begin(), y.end(), Scalar(0));
    for (std::int64_t c = 0; c < size; ++c)
        for (std::int64_t k = column_start[c]; k < column_start[c + 1]; ++k)
        {
            const std::int64_t r = row[k];
            y[r] += value[k] * x[c];
            if (r != c)
                y[c] += value[k] * x[r];
        }
}

namespace {

// CHOLMOD is loaded on the first factorization, not with the program: its BLAS
// (OpenBLAS) starts a thread pool when it is loaded, which every process would pay for
// (about 3 ms, and threads that a traced or forked process does not expect), although
// only the direct method needs it. The library's name is its SONAME, found by CMake.
struct CholmodLibrary
{
    decltype(&cholmod_l_start) start = nullptr;
    decltype(&cholmod_l_finish) finish = nullptr;
    decltype(&cholmod_l_analyze) analyze = nullptr;
    decltype(&cholmod_l_factorize) factorize = nullptr;
    decltype(&cholmod_l_solve) solve = nullptr;
    decltype(&cholmod_l_free_factor) free_factor = nullptr;
    decltype(&cholmod_l_free_dense) free_dense = nullptr;
    // OpenBLAS's thread count, when the BLAS CHOLMOD loaded is OpenBLAS (else null).
    void (*set_blas_threads)(int) = nullptr;
    int blas_threads = 1;            //!< its count at load (all cores, or OPENBLAS_NUM_THREADS)
    bool blas_threads_given = false; //!< OPENBLAS_NUM_THREADS (or GOTO_NUM_THREADS) set
};

// Below this many floating-point operations a factorization runs its BLAS on one thread.
// OpenBLAS's pthread build keeps a pool of its own beside OpenMP's, and both wait for work
// by spinning: on small supernodes its threads mostly wait for a core the other pool
// holds. On the 35k bunny's region (0.14 Gflop, 2 cores) one BLAS thread took the first
// result from 170 to 86 ms and a re-solve from 44 to 5.2 ms (medians of 7,
// docs/performance.md); at 1.25M vertices (22 Gflop) two threads factor faster (2.8 s
// against 3.1 s). The same matrix always takes the same count, so the bits never
// depend on which program factors it.
constexpr double kOneBlasThreadBelowFlops = 2e9;

// The expected lengths of the phases a PreparationProgress shows: the ordering's seconds
// per stored nonzero of A and the factorization's operations per second, as this process
// last measured them on a matrix large enough to time; until then, this machine's figures
// at 1.25M vertices (docs/performance.md: 7.1 s for 4.1 M nonzeros; 22 Gflop in 2.8-5 s).
std::atomic<double> ordering_seconds_per_nonzero{1.5e-6};
std::atomic<double> factor_flops_per_second{4e9};
constexpr double kTimedNonzeros = 1e5; // smaller analyses say little of larger ones

// From this many unknowns the ordering is METIS's nested dissection alone. CHOLMOD's
// default tries AMD first and METIS only when AMD's fill is high, which on a surface mesh
// it always is at this size: at 1.21M unknowns AMD took 1.1 s to give a factor of 78 Gflop
// that METIS's ordering (6.5-7.5 s) cuts to 23 Gflop. Below it AMD alone is kept (35k: 24 ms
// against METIS's 140 ms, for a factorization no slower).
constexpr std::int64_t kNestedDissectionFrom = 200000;
constexpr double kTimedFlops = 1e8;

// CHOLMOD 3's supernodal factorization and solve fork OpenMP teams of a fixed four threads
// (CHOLMOD_OMP_NUM_THREADS, a constant of its build, not OMP_NUM_THREADS) for loops inside
// each supernode: on a small factor the forks and joins cost more than the loops. On the
// 35k bunny's region (3,764 supernodes) the factorization takes 39 ms with them and 29 ms
// without (15 repetitions each, two cores), the same bits: the loops only clear and copy.
// While a small factor's CHOLMOD call runs, no OpenMP region of the process may be active
// (max-active-levels 0, restored by the last such call to end): other threads' loops run on
// one thread for those milliseconds.
class SerialOpenMpRegions
{
public:
    explicit SerialOpenMpRegions(bool serial) : serial_(serial)
    {
        if (!serial_)
            return;
        std::lock_guard lock(mutex());
        if (holders()++ == 0)
        {
            saved() = omp_get_max_active_levels();
            omp_set_max_active_levels(0);
        }
    }
    ~SerialOpenMpRegions()
    {
        if (!serial_)
            return;
        std::lock_guard lock(mutex());
        if (--holders() == 0)
            omp_set_max_active_levels(saved());
    }
    SerialOpenMpRegions(const SerialOpenMpRegions&) = delete;
    SerialOpenMpRegions& operator=(const SerialOpenMpRegions&) = delete;

private:
    bool serial_;
    static std::mutex& mutex()
    {
        static std::mutex m;
        return m;
    }
    static int& holders()
    {
        static int n = 0;
        return n;
    }
    static int& saved()
    {
        static int levels = 1;
        return levels;
    }
};

template <class Function>
void bind(void* handle, const char* name, Function& f)
{
    f = reinterpret_cast<Function>(dlsym(handle, name));
    if (f == nullptr)
        throw SolverError(std::string("sparse Cholesky: ") + MESHFAIR_CHOLMOD_LIBRARY + " has no " +
                          name);
}

const CholmodLibrary& cholmod_library()
{
    static CholmodLibrary library;
    static std::string failure;
    static std::once_flag once;
    std::call_once(once, [] {
        // Never unloaded: the factor and the BLAS threads live as long as the process.
        void* handle = dlopen(MESHFAIR_CHOLMOD_LIBRARY, RTLD_NOW | RTLD_LOCAL);
        if (handle == nullptr)
        {
            const char* reason = dlerror();
            failure = std::string("sparse Cholesky: cannot load ") + MESHFAIR_CHOLMOD_LIBRARY +
                      " (Debian package libcholmod3): " + (reason ? reason : "unknown reason");
            return;
        }
        try
        {
            bind(handle, "cholmod_l_start", library.start);
            bind(handle, "cholmod_l_finish", library.finish);
            bind(handle, "cholmod_l_analyze", library.analyze);
            bind(handle, "cholmod_l_factorize", library.factorize);
            bind(handle, "cholmod_l_solve", library.solve);
            bind(handle, "cholmod_l_free_factor", library.free_factor);
            bind(handle, "cholmod_l_free_dense", library.free_dense);
            // The BLAS CHOLMOD loaded with it (Debian's alternatives choose it), if it is
            // OpenBLAS: its thread count is set per factorization (kOneBlasThreadBelowFlops),
            // unless the environment sets it.
            for (const char* blas : {"libblas.so.3", "libopenblas.so.0"})
                if (void* b = dlopen(blas, RTLD_NOW | RTLD_NOLOAD))
                {
                    using Get = int (*)();
                    const auto get = reinterpret_cast<Get>(dlsym(b, "openblas_get_num_threads"));
                    library.set_blas_threads =
                        reinterpret_cast<void (*)(int)>(dlsym(b, "openblas_set_num_threads"));
                    if (get == nullptr)
                        library.set_blas_threads = nullptr;
                    if (library.set_blas_threads != nullptr)
                    {
                        library.blas_threads = get();
                        // (OMP_NUM_THREADS, which OpenBLAS also reads, sets MeshFair's
                        // threads: it is the count of large factors, not a rule for all.)
                        library.blas_threads_given =
                            std::getenv("OPENBLAS_NUM_THREADS") || std::getenv("GOTO_NUM_THREADS");
                        break;
                    }
                }
        }
        catch (const SolverError& e)
        {
            failure = e.what();
        }
    });
    if (!failure.empty())
        throw SolverError(failure);
    return library;
}

} // namespace

struct SparseCholesky::Cholmod
{
    const CholmodLibrary& library = cholmod_library();
    cholmod_common common{};
    cholmod_factor* factor = nullptr;
};

namespace {

// The matrix as CHOLMOD's view of our arrays: no copy of the indices or values.
cholmod_sparse view(const SymmetricMatrix& a)
{
    cholmod_sparse s{};
    s.nrow = static_cast<size_t>(a.size);
    s.ncol = static_cast<size_t>(a.size);
    s.nzmax = a.row.size();
    // CHOLMOD reads these only: its interface is not const-qualified.
    s.p = const_cast<std::int64_t*>(a.column_start.data());
    s.i = const_cast<std::int64_t*>(a.row.data());
    s.x = const_cast<Scalar*>(a.value.data());
    s.stype = 1; // the upper triangle
    s.itype = CHOLMOD_LONG;
    s.xtype = CHOLMOD_REAL;
    s.dtype = CHOLMOD_DOUBLE;
    s.sorted = 1;
    s.packed = 1;
    return s;
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void check_matrix(const SymmetricMatrix& a, const char* what)
{
    if (a.size < 0 || a.column_start.size() != static_cast<size_t>(a.size) + 1 ||
        a.row.size() != a.value.size() ||
        a.column_start.back() != static_cast<std::int64_t>(a.row.size()))
        throw SolverError(std::string("SparseCholesky::") + what + ": malformed matrix");
}

// A digest of the pattern (the column starts and the rows), so that a session keeps no
// copy of it (40 bytes a vertex at the sizes where skipping the analysis matters) to tell
// whether a new matrix has it. FNV-1a over 64-bit words, each mixed first (splitmix64's
// finalizer) so that small index differences spread over every bit.
std::uint64_t pattern_digest(const SymmetricMatrix& a)
{
    std::uint64_t h = 0xcbf29ce484222325ULL;
    const auto add = [&h](std::uint64_t w) {
        w ^= w >> 30;
        w *= 0xbf58476d1ce4e5b9ULL;
        w ^= w >> 27;
        w *= 0x94d049bb133111ebULL;
        w ^= w >> 31;
        h = (h ^ w) * 0x100000001b3ULL;
    };
    add(static_cast<std::uint64_t>(a.size));
    for (const std::int64_t c : a.column_start)
        add(static_cast<std::uint64_t>(c));
    for (const std::int64_t r : a.row)
        add(static_cast<std::uint64_t>(r));
    return h;
}

} // namespace

SparseCholesky::SparseCholesky() : cholmod_(std::make_unique<Cholmod>())
{
    cholmod_common& c = cholmod_->common;
    cholmod_->library.start(&c);
    c.print = 0; // the library never prints; failures come back as exceptions
    c.supernodal = CHOLMOD_SUPERNODAL;
    // Never fall back to a partial factor: a matrix that is not positive definite is
    // reported as such (factor() returns false).
    c.quick_return_if_not_posdef = 1;
}

SparseCholesky::~SparseCholesky()
{
    cholmod_common& c = cholmod_->common;
    if (cholmod_->factor != nullptr)
        cholmod_->library.free_factor(&cholmod_->factor, &c);
    cholmod_->library.finish(&c);
}

void SparseCholesky::analyse(const SymmetricMatrix& a)
{
    check_matrix(a, "analyse");
    cholmod_common& c = cholmod_->common;
    if (cholmod_->factor != nullptr)
        cholmod_->library.free_factor(&cholmod_->factor, &c);
    factored_ = false;
    size_ = a.size;
    stats_ = {};
    const double nonzeros = static_cast<double>(a.row.size());
    if (progress_)
        progress_->enter(PreparationProgress::Phase::Ordering, a.size, 0,
                         nonzeros * ordering_seconds_per_nonzero);
    c.nmethods = a.size >= kNestedDissectionFrom ? 1 : 0; // 0: CHOLMOD's default choice
    c.method[0].ordering = CHOLMOD_METIS;
    const auto start = std::chrono::steady_clock::now();
    cholmod_sparse s = view(a);
    {
        const SerialOpenMpRegions serial(a.size < kNestedDissectionFrom);
        cholmod_->factor = cholmod_->library.analyze(&s, &c);
    }
    if (cholmod_->factor == nullptr || c.status < CHOLMOD_OK)
        throw SolverError(c.status == CHOLMOD_OUT_OF_MEMORY
                              ? "sparse Cholesky: out of memory in the analysis"
                              : "sparse Cholesky: the analysis failed (CHOLMOD status " +
                                    std::to_string(c.status) + ")");
    stats_.analyse_seconds = seconds_since(start);
    if (nonzeros >= kTimedNonzeros)
        ordering_seconds_per_nonzero = stats_.analyse_seconds / nonzeros;
    stats_.factor_nonzeros = c.lnz;
    stats_.factor_flops = c.fl;
    pattern_digest_ = pattern_digest(a);
    pattern_nonzeros_ = static_cast<std::int64_t>(a.row.size());
}

void SparseCholesky::use_blas_threads() const
{
    const CholmodLibrary& library = cholmod_->library;
    if (library.set_blas_threads != nullptr && !library.blas_threads_given)
        library.set_blas_threads(
            stats_.factor_flops < kOneBlasThreadBelowFlops ? 1 : library.blas_threads);
}

bool SparseCholesky::analysed_for(const SymmetricMatrix& a) const
{
    return cholmod_->factor != nullptr && a.size == size_ &&
           static_cast<std::int64_t>(a.row.size()) == pattern_nonzeros_ &&
           a.column_start.size() == static_cast<size_t>(a.size) + 1 &&
           pattern_digest(a) == pattern_digest_;
}

bool SparseCholesky::factor(const SymmetricMatrix& a)
{
    check_matrix(a, "factor");
    if (cholmod_->factor == nullptr || a.size != size_)
        throw SolverError("SparseCholesky::factor: analyse this pattern first");
    cholmod_common& c = cholmod_->common;
    factored_ = false;
    if (progress_)
        progress_->enter(PreparationProgress::Phase::Factoring, a.size, stats_.factor_flops,
                         stats_.factor_flops / factor_flops_per_second);
    const auto start = std::chrono::steady_clock::now();
    cholmod_sparse s = view(a);
    use_blas_threads();
    {
        const SerialOpenMpRegions serial(stats_.factor_flops < kOneBlasThreadBelowFlops);
        cholmod_->library.factorize(&s, cholmod_->factor, &c);
    }
    stats_.factor_seconds = seconds_since(start);
    if (stats_.factor_flops >= kTimedFlops && stats_.factor_seconds > 0)
        factor_flops_per_second = stats_.factor_flops / stats_.factor_seconds;
    if (stats_.factorizations++ > 0)
        stats_.analyse_seconds = 0; // this matrix's analysis: none, the pattern's was kept
    if (c.status == CHOLMOD_NOT_POSDEF)
        return false;
    if (c.status < CHOLMOD_OK)
        throw SolverError(c.status == CHOLMOD_OUT_OF_MEMORY
                              ? "sparse Cholesky: out of memory in the factorization"
                              : "sparse Cholesky: the factorization failed (CHOLMOD status " +
                                    std::to_string(c.status) + ")");
    // The supernodal factor's own count (with the zeros its supernodes hold).
    const cholmod_factor* f = cholmod_->factor;
    if (f->is_super && f->xsize > 0)
        stats_.factor_nonzeros = static_cast<double>(f->xsize);
    factored_ = true;
    return true;
}

void SparseCholesky::solve(std::span<Scalar> b, int columns) const
{
    if (!factored_)
        throw SolverError("SparseCholesky::solve: no factorization");
    if (columns < 1 || b.size() != static_cast<size_t>(size_) * static_cast<size_t>(columns))
        throw SolverError("SparseCholesky::solve: the right-hand side has the wrong size");
    if (size_ == 0)
        return;
    cholmod_common& c = cholmod_->common;
    cholmod_dense rhs{};
    rhs.nrow = static_cast<size_t>(size_);
    rhs.ncol = static_cast<size_t>(columns);
    rhs.nzmax = b.size();
    rhs.d = static_cast<size_t>(size_);
    rhs.x = b.data();
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    use_blas_threads();
    cholmod_dense* x = nullptr;
    {
        const SerialOpenMpRegions serial(stats_.factor_flops < kOneBlasThreadBelowFlops);
        x = cholmod_->library.solve(CHOLMOD_A, cholmod_->factor, &rhs, &c);
    }
    if (x == nullptr)
        throw SolverError(c.status == CHOLMOD_OUT_OF_MEMORY
                              ? "sparse Cholesky: out of memory in the solve"
                              : "sparse Cholesky: the solve failed");
    const Scalar* values = static_cast<const Scalar*>(x->x);
    std::copy(values, values + b.size(), b.begin());
    cholmod_->library.free_dense(&x, &c);
}

} // namespace meshfair
