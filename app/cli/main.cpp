// probecycle-cli: the probing-cycle model on the command line.

#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "app/cli/cli_common.h"
#include "app/cli/commands.h"
#include "core/cycle/scenario.h"

namespace {

constexpr const char* kUsage = R"(usage: probecycle-cli COMMAND [ARGS]

Cycle model:
  defaults                                   print the default scenario (JSON)
  evaluate [SCENARIO.json] [--set K=V ...]   cycle time, overtravel, phases, warnings (JSON)
  move [SCENARIO.json] [--set K=V ...] --distance MM --feed MM_MIN
                                             one rest-to-rest move (JSON)
  sweep [SCENARIO.json] [--set K=V ...] --from F0 --to F1 --step DF [--csv FILE]
        [--recommended-backoff]              cycle time against probe feed (CSV); with
                                             --recommended-backoff, two-touch backs off
                                             overtravel + reseat at each feed
  report [SCENARIO.json] [--set K=V ...] [--csv FILE]
                                             the CSV report the window exports
  montecarlo [SCENARIO.json] [--set K=V ...] [--samples N] [--seed S] [--bins B]
                                             trigger-error histogram (JSON)
Calibration and latency lab:
  calibrate ring FILE.csv --gauge-diameter MM [--runout-limit MM] [--residual-limit MM]
        [--report FILE.csv]                  ring-gauge calibration: centre, runout, radius
  calibrate length --surface-z MM --trigger-z MM [--trigger-z MM ...] [--active-length MM]
        [--nominal-length MM] [--wear-limit MM]
                                             effective probe length, or wear
  latency fit FILE.csv [--interpolation-period-s S] [--apply-to SCENARIO.json] [--group X+]
                                             delay from touches at several feeds
  latency compensate [SCENARIO.json] [--set K=V ...] [--touch constant|braking] ...
                                             compare trigger-position compensations
                                             ('latency help' lists every option)

--set section.key=value overrides one scenario key, e.g. --set cycle.probe_feed_mm_min=1500.
Exit status: 0 on success, 2 on bad input or usage (the message is on stderr).
)";

}  // namespace

int main(int argc, char** argv) {
    using namespace probecycle;
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        (args.empty() ? std::cerr : std::cout) << kUsage;
        return args.empty() ? 2 : 0;
    }
    const std::string& command = args[0];
    const std::span<const std::string> rest(args.data() + 1, args.size() - 1);
    try {
        if (command == "defaults") return cli::run_defaults(rest);
        if (command == "evaluate") return cli::run_evaluate(rest);
        if (command == "move") return cli::run_move(rest);
        if (command == "sweep") return cli::run_sweep(rest);
        if (command == "report") return cli::run_report(rest);
        if (command == "montecarlo") return cli::run_montecarlo(rest);
        if (command == "calibrate") return cli::run_calibrate(rest);
        if (command == "latency") return cli::run_latency(rest);
        std::cerr << "probecycle-cli: unknown command '" << command
                  << "'; allowed: defaults, evaluate, move, sweep, report, montecarlo, calibrate, "
                     "latency\n";
        return 2;
    } catch (const ScenarioError& e) {
        std::cerr << "probecycle-cli: invalid scenario:\n" << e.what() << '\n';
    } catch (const std::exception& e) {
        std::cerr << "probecycle-cli " << command << ": " << e.what() << '\n';
    }
    return 2;
}
