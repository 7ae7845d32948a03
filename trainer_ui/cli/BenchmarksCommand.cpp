/// \file
/// `colonosim benchmarks derive --name SET --from-user EXPERT --as ADMIN [--k K]`:
/// a new version of a benchmark set, derived from the completed sessions of an
/// expert user on the tasks that use SET (mean ± k·SD per metric,
/// scoring/Benchmarks.h); then every completed session of those tasks is
/// re-scored from its stored recording against the new version (the old
/// scores are replaced through the audited data-access layer, never by hand).
/// `colonosim benchmarks show --name SET --as NAME` prints the latest version.

#include "curricula/Curriculum.h"
#include "db/RecordingCodec.h"
#include "scoring/Benchmarks.h"
#include "scoring/DomainScores.h"
#include "trainer_ui/cli/Commands.h"
#include "trainer_ui/cli/RecordsAccess.h"

#include <iostream>
#include <set>

namespace colonosim::cli {

int runBenchmarks(std::span<char* const> args)
{
    std::vector<std::string> options = {"--name", "--from-user", "--k"};
    options.insert(options.end(), kRecordsOptions.begin(), kRecordsOptions.end());
    const CommandLine line(args, {"--help"}, options);
    const auto& words = line.positional();
    if (line.has("--help") || words.size() != 1 || (words[0] != "derive" && words[0] != "show")) {
        std::cout << "usage: colonosim benchmarks derive --name SET --from-user EXPERT --as ADMIN [--k K]\n"
                     "       colonosim benchmarks show --name SET --as NAME\n"
                     "  --k K   band width in expert standard deviations, 0-4 (default 1)\n"
                     "derive stores a new version and re-scores past sessions from their recordings.\n";
        return line.has("--help") ? 0 : 2;
    }
    const auto name = line.value("--name");
    if (!name) {
        throw UsageError("--name SET is required");
    }
    const auto curriculum =
        curricula::parseCurriculum(curricula::coreCurriculumXml(), "colonoscopy-core.xml");
    std::set<std::string> tasks;
    for (const auto& t : curriculum.value->tasks) {
        if (t.benchmark == *name) {
            tasks.insert(t.id);
        }
    }
    if (tasks.empty()) {
        throw UsageError("--name = " + *name + " is not the benchmark set of any colonoscopy-core task");
    }
    OpenRecords open = openRecords(line, std::cerr);
    const db::Actor actor = authenticate(*open.records, line, line.value("--as").value_or(""));
    if (words[0] == "show") {
        const auto stored = open.records->latestBenchmarkSet(*name);
        if (!stored) {
            std::cout << "no benchmark set " << *name << " stored yet\n";
            return 0;
        }
        std::cout << std::get<2>(*stored) << '\n';
        return 0;
    }
    const auto expert = line.value("--from-user");
    if (!expert) {
        throw UsageError("--from-user EXPERT is required");
    }
    const double k =
        line.number("--k", scoring::BenchmarkSet::kSpec.defaultValue, scoring::BenchmarkSet::kSpec.minValue,
                    scoring::BenchmarkSet::kSpec.maxValue, "SD");
    try {
        std::vector<scoring::MetricValues> runs;
        for (const auto& s : open.records->sessions(actor, *expert)) {
            if (tasks.contains(s.task)) {
                runs.push_back(s.metrics);
            }
        }
        if (runs.size() < 2) {
            throw UsageError("--from-user = " + *expert + " has " + std::to_string(runs.size()) +
                             " completed session(s) on the tasks of " + *name + "; at least 2 are needed");
        }
        const auto previous = open.records->latestBenchmarkSet(*name);
        const int version = previous ? std::get<1>(*previous) + 1 : 1;
        const scoring::BenchmarkSet set = scoring::deriveBenchmarks(*name, version, k, runs);
        const qint64 id = open.records->storeBenchmarkSet(actor, *name, version, set.toJson());
        int rescored = 0;
        for (const auto& u : open.records->listUsers(actor)) {
            for (const auto& s : open.records->sessions(actor, u.name)) {
                if (!tasks.contains(s.task)) {
                    continue;
                }
                const QByteArray blob = open.records->sessionRecording(actor, s.id);
                const procedure::Recording recording =
                    db::decodeRecording(std::vector<char>(blob.begin(), blob.end()));
                // Lesions present, the colon's length and the renderer's coverage as stored.
                const scoring::ScoringContext context = scoring::storedContext(s.metrics);
                const scoring::MetricValues values = scoring::computeMetrics(recording, context);
                auto scores = scoring::scoreSession(values, set);
                scores["benchmark_met"] = set.met(values) ? 1.0 : 0.0;
                open.records->rescore(actor, s.id, scores, id);
                ++rescored;
            }
        }
        std::cout << "benchmark set " << *name << " version " << version << " from " << runs.size()
                  << " session(s) of " << *expert << " (k = " << k << "); " << rescored
                  << " session(s) re-scored from their recordings\n";
    } catch (const db::AccessDenied& error) {
        throw UsageError(std::string("refused: ") + error.what());
    } catch (const db::DatabaseError& error) {
        throw UsageError(error.what());
    }
    return 0;
}

}  // namespace colonosim::cli
