// LeakSanitizer settings for this test program. OpenCASCADE's data-exchange libraries register
// process-wide statics once (Interface_Static, the STEP controller's editors) and never free
// them, and its STEP writer (used here to make fixtures) leaks a direction per shape. Those are
// suppressed by function name; OpenCASCADE is built without frame pointers, so allocation
// stacks are unwound the slow way for the names to be seen. Any other leak still fails the run.
#if defined(__SANITIZE_ADDRESS__)

extern "C" __attribute__((used, visibility("default"))) const char* __asan_default_options()
{
  return "fast_unwind_on_malloc=0";
}

extern "C" __attribute__((used, visibility("default"))) const char* __lsan_default_suppressions()
{
  return "leak:Interface_Static::Init\n"
         "leak:STEPControl_Controller::STEPControl_Controller\n"
         "leak:GeomToStep_MakeDirection::GeomToStep_MakeDirection\n";
}

#endif
