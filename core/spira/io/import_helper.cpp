// spira-import's body: runs one importer with limits on its own memory and processor time and
// streams the result to the parent (see import_wire.h).
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <iostream>
#include <new>
#include <nlohmann/json.hpp>

#include "spira/base/error.h"
#include "spira/io/import_wire.h"
#include "spira/io/isolated_import.h"

namespace spira {
namespace {

constexpr int kResultFd = 3;

// Forwards progress to the parent, at most one frame per percent or stage change.
class WireProgress final : public Progress {
 public:
  explicit WireProgress(wire::Writer& out) : out_(out) {}
  void report(double fraction, std::string_view stage) override
  {
    fraction = std::clamp(fraction, 0.0, 1.0);
    if (stage == stage_ && std::abs(fraction - last_) < 0.01) return;
    stage_ = stage;
    last_ = fraction;
    out_.progress(fraction, stage);
  }
  bool cancelled() const override { return false; }  // the parent cancels by killing the helper

 private:
  wire::Writer& out_;
  std::string stage_;
  double last_ = -1.0;
};

void limit(int resource, rlim_t value)
{
  const rlimit r{value, value};
  ::setrlimit(resource, &r);
}

int runImporter(char** argv, const PluginRegistry& registry)
{
#ifndef __SANITIZE_ADDRESS__  // AddressSanitizer's shadow memory alone is terabytes of address space
  limit(RLIMIT_AS, std::stoull(argv[4]));
#endif
  limit(RLIMIT_CPU, std::stoull(argv[5]));
  limit(RLIMIT_CORE, 0);
  wire::Writer out(kResultFd);
  out.header();
  try {
    const ImporterPlugin& importer = registry.importer(argv[1]);
    const ParamSet params = ParamSet::fromJson(nlohmann::json::parse(argv[3]), &importer.schema());
    WireProgress progress(out);
    out.mesh(importer.read(argv[2], params, progress));
  } catch (const InputError& e) {
    out.error(wire::ErrorKind::Input, e.what(), e.hint());
  } catch (const IoError& e) {
    out.error(wire::ErrorKind::Io, e.what(), e.hint());
  } catch (const AlgorithmError& e) {
    out.error(wire::ErrorKind::Algorithm, e.what(), e.hint());
  } catch (const Error& e) {
    out.error(wire::ErrorKind::Internal, e.what(), e.hint());
  } catch (const std::bad_alloc&) {
    out.error(wire::ErrorKind::Memory, {}, {});
  } catch (const std::exception& e) {
    out.error(wire::ErrorKind::Internal, std::string("importer '") + argv[1] + "' failed: " + e.what(),
              "please report this with the file");
  }
  return 0;
}

}  // namespace

int importHelperMain(int argc, char** argv, const PluginRegistry& registry)
{
  // Dies with the parent: an orphaned parser must not keep running.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() == 1) return 1;
  if (argc != 6) {
    std::cerr << "usage: spira-import IMPORTER_ID FILE PARAMS_JSON MEMORY_BYTES CPU_SECONDS (run by Spira, "
                 "not by hand)\n";
    return 2;
  }
  int status = 1;  // the parent is gone or the arguments are not Spira's: nobody left to tell
  try {
    status = runImporter(argv, registry);
  } catch (const std::exception&) {
  }
  // The result is written: skip the libraries' exit handlers, which can hang once memory ran out
  // (OpenBLAS joins a thread stuck on a failed mmap) and only cost time.
  ::_exit(status);
}

}  // namespace spira
