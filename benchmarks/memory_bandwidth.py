#!/usr/bin/env python3
"""What this machine allows a memory-bound sparse kernel: the bandwidth of a
CSR matrix-vector product (8-byte values, 4-byte columns, 18 entries per
row as in 2-D Q1 elasticity) far beyond the caches, run by one process
alone and by two processes at once. The estimates of doc/profiling.md and
the strong-scaling discussion of doc/parallel.md quote it.

  python3 benchmarks/memory_bandwidth.py [--rows 3000000] [--repeats 20]

Prints GB/s per process (best of the repeats and mean) for 1 and 2
concurrent processes.
"""
import argparse
import subprocess
import tempfile
from pathlib import Path

KERNEL = r"""
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>
int main(int argc, char **argv) {
  const size_t n = atol(argv[1]), per = 18, nnz = n * per;
  const int reps = atoi(argv[2]);
  std::vector<double> val(nnz, 1.0), x(n, 1.0), y(n);
  std::vector<int> col(nnz), ptr(n + 1);
  for (size_t i = 0; i <= n; ++i) ptr[i] = i * per;
  // a banded pattern, as a numbered mesh gives
  for (size_t i = 0; i < n; ++i)
    for (size_t k = 0; k < per; ++k) col[i * per + k] = (i + (k - 9) * 7 + n) % n;
  double best = 1e9, total = 0;
  for (int r = 0; r < reps; ++r) {
    const auto s = std::chrono::steady_clock::now();
    for (size_t i = 0; i < n; ++i) {
      double sum = 0;
      for (int k = ptr[i]; k < ptr[i + 1]; ++k) sum += val[k] * x[col[k]];
      y[i] = sum;
    }
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - s).count();
    best = t < best ? t : best;
    total += t;
  }
  const double bytes = nnz * 12.0 + n * 20.0;
  printf("%.2f %.2f %g\n", bytes / best / 1e9, bytes / (total / reps) / 1e9, y[n / 2]);
}
"""


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rows", type=int, default=3000000)
    ap.add_argument("--repeats", type=int, default=20)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        src, exe = Path(tmp) / "csr.cc", Path(tmp) / "csr"
        src.write_text(KERNEL)
        subprocess.run(["g++", "-O3", "-march=native", str(src), "-o", str(exe)], check=True)
        cmd = [str(exe), str(args.rows), str(args.repeats)]
        mb = args.rows * (18 * 12 + 20) / 1e6
        print(f"CSR matrix-vector product, {args.rows} rows, {mb:.0f} MB per product")
        for copies in (1, 2):
            procs = [subprocess.Popen(cmd, stdout=subprocess.PIPE, text=True) for _ in range(copies)]
            results = [p.communicate()[0].split() for p in procs]
            per = ", ".join(f"{float(r[0]):.1f} best / {float(r[1]):.1f} mean" for r in results)
            print(f"{copies} process(es) at once: GB/s per process {per}")


if __name__ == "__main__":
    main()
