// A Google Benchmark console reporter that also keeps each benchmark's adjusted real time per
// iteration (ns; the median when the benchmark has repetitions), so a program can print ratios
// between benchmarks of the same run.
#ifndef lct_bench_RecordingReporter_h
#define lct_bench_RecordingReporter_h

#include <benchmark/benchmark.h>

#include <cstring>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace lct_bench
{

class RecordingReporter : public benchmark::ConsoleReporter
{
public:
  std::map<std::string, double> nanoseconds;

  void ReportRuns(const std::vector<Run>& runs) override
  {
    for (const Run& run : runs)
    {
      // With repetitions, the median of the repetitions stands for the benchmark: a ratio of
      // two medians is stable on a shared machine where single runs drift by 10 %.
      if (run.run_type == Run::RT_Iteration)
      {
        this->nanoseconds.emplace(run.run_name.str(), run.GetAdjustedRealTime());
      }
      else if (run.aggregate_name == "median")
      {
        this->nanoseconds[run.run_name.str()] = run.GetAdjustedRealTime();
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }

  /// The time of benchmark `name`, 0 if it did not run (filtered out).
  double Get(const std::string& name) const
  {
    const auto it = this->nanoseconds.find(name);
    return it == this->nanoseconds.end() ? 0.0 : it->second;
  }
};

/// The main of a benchmark program that prints a table of ratios or goals after the runs:
/// `--check` is taken out of the arguments and handed to `table`, whose value is the exit status.
inline int runWithTable(
  int argc, char** argv, const std::function<int(const RecordingReporter&, bool check)>& table)
{
  bool check = false;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--check") == 0)
    {
      check = true;
    }
    else
    {
      args.push_back(argv[i]);
    }
  }
  int n = static_cast<int>(args.size());
  benchmark::Initialize(&n, args.data());
  RecordingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  const int status = table(reporter, check);
  benchmark::Shutdown();
  return status;
}

} // namespace lct_bench

#endif
