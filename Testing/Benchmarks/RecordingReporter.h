// A Google Benchmark console reporter that also keeps each benchmark's adjusted real time per
// iteration (ns; the median when the benchmark has repetitions), so a program can print ratios
// between benchmarks of the same run.
#ifndef lct_bench_RecordingReporter_h
#define lct_bench_RecordingReporter_h

#include <benchmark/benchmark.h>

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

} // namespace lct_bench

#endif
