// POLYDEM kernel tests: sanitizer defaults. The CGAL reference (built without
// sanitizers) allocates heavily; recording a stack trace per malloc made the
// suite 20x slower. Kernels never allocate, so their reports lose nothing.
extern "C" const char *__asan_default_options()
{
  return "malloc_context_size=0:detect_leaks=0:quarantine_size_mb=0:"
         "thread_local_quarantine_size_kb=0:max_malloc_fill_size=0";
}
