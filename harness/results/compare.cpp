#include "harness/results/compare.h"

#include "harness/results/markup_escape.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>

namespace holebench::harness {

const char* to_string(MetricVerdict verdict) {
  switch (verdict) {
    case MetricVerdict::Unchanged:
      return "unchanged";
    case MetricVerdict::WithinTolerance:
      return "within tolerance";
    case MetricVerdict::Improved:
      return "improved";
    case MetricVerdict::Regressed:
      return "REGRESSION";
    case MetricVerdict::NotJudged:
      return "not judged";
    case MetricVerdict::Appeared:
      return "appeared";
    case MetricVerdict::Disappeared:
      return "disappeared";
  }
  return "?";
}

const char* to_string(JobPresence presence) {
  switch (presence) {
    case JobPresence::Both:
      return "both";
    case JobPresence::Missing:
      return "missing";
    case JobPresence::New:
      return "new";
  }
  return "?";
}

bool JobComparison::status_regressed() const {
  return old_status && new_status && *old_status == JobStatus::Ok && *new_status != JobStatus::Ok;
}

bool JobComparison::regression() const {
  if (presence == JobPresence::Missing || status_regressed())
    return true;
  return std::any_of(metrics.begin(), metrics.end(),
                     [](const MetricChange& m) { return m.regression(); });
}

std::vector<const MetricChange*> JobComparison::regressed_metrics() const {
  std::vector<const MetricChange*> regressed;
  for (const auto& m : metrics) {
    if (m.regression())
      regressed.push_back(&m);
  }
  return regressed;
}

bool Comparison::has_regression() const {
  return std::any_of(jobs.begin(), jobs.end(),
                     [](const JobComparison& j) { return j.regression(); });
}

std::size_t Comparison::regressed_jobs() const {
  return static_cast<std::size_t>(std::count_if(
      jobs.begin(), jobs.end(), [](const JobComparison& j) { return j.regression(); }));
}

namespace {

/// Judges one metric present on both sides.
MetricChange judge(const std::string& name, double old_value, double new_value,
                   const Tolerances& tolerances) {
  MetricChange m;
  m.metric = name;
  m.old_value = old_value;
  m.new_value = new_value;
  if (old_value == new_value || (std::isnan(old_value) && std::isnan(new_value))) {
    m.verdict = MetricVerdict::Unchanged;
    return m;
  }
  m.change = new_value - old_value;
  if (old_value == 0.0) {
    // Relative change from zero is unbounded: report it as +-infinity and judge the change
    // by the absolute tolerance alone (relative * |old| is 0).
    m.from_zero = true;
    m.relative_change = std::isnan(m.change) ? m.change
                        : m.change > 0.0     ? std::numeric_limits<double>::infinity()
                                             : -std::numeric_limits<double>::infinity();
  } else {
    m.relative_change = m.change / std::fabs(old_value);
  }
  const std::optional<MetricTolerance> tolerance = tolerances.find(name);
  if (!tolerance) {
    m.verdict = MetricVerdict::NotJudged;
    return m;
  }
  m.allowed = std::isfinite(old_value)
                  ? std::max(tolerance->absolute, tolerance->relative * std::fabs(old_value))
                  : tolerance->absolute;
  if (std::isnan(new_value)) {
    m.verdict = MetricVerdict::Regressed;  // a number became not-a-number
  } else if (std::isnan(old_value)) {
    m.verdict = MetricVerdict::Improved;
  } else {
    const double worse_by = tolerance->lower_is_better ? m.change : -m.change;
    if (worse_by > m.allowed) {
      m.verdict = MetricVerdict::Regressed;
    } else if (-worse_by > m.allowed) {
      m.verdict = MetricVerdict::Improved;
    } else {
      m.verdict = MetricVerdict::WithinTolerance;
    }
  }
  return m;
}

std::map<std::string, const JobRecord*> by_id(const ResultsData& data) {
  std::map<std::string, const JobRecord*> records;
  for (const auto& record : data.records)
    records[record.job.id()] = &record;  // last one wins
  return records;
}

std::string setting_text(const MethodOptionValue* value) {
  if (!value)
    return "-";
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool>)
          return v ? "true" : "false";
        else if constexpr (std::is_same_v<T, std::string>)
          return v;
        else
          return fmt::format("{}", v);
      },
      *value);
}

// The built-in method's settings that differ between two jobs, "name: old -> new"; none where
// either job names no settings (an older record, an external method).
std::vector<std::string> changed_settings(const Job& old_job, const Job& new_job) {
  std::vector<std::string> changed;
  const MethodOptions& a = old_job.method_options;
  const MethodOptions& b = new_job.method_options;
  if (a.empty() || b.empty())
    return changed;
  for (const auto& option : a.values()) {
    const MethodOptionValue* other = b.find(option.name);
    if (!other || *other != option.value)
      changed.push_back(fmt::format("{}: {} -> {}", option.name, setting_text(&option.value),
                                    setting_text(other)));
  }
  for (const auto& option : b.values()) {
    if (!a.find(option.name))
      changed.push_back(fmt::format("{}: - -> {}", option.name, setting_text(&option.value)));
  }
  return changed;
}

// The names of the metrics of either record, sorted, each once.
std::vector<std::string> metric_names_of(const JobRecord& a, const JobRecord& b) {
  std::vector<std::string> names;
  for (const auto* record : {&a, &b}) {
    for (const auto& metric : record->metrics)
      names.push_back(metric.name);
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

}  // namespace

Comparison compare_results(const ResultsData& base, const ResultsData& now,
                           const Tolerances& tolerances) {
  Comparison comparison;
  comparison.base_label = base.context.code_version;
  comparison.new_label = now.context.code_version;
  const auto old_records = by_id(base);
  const auto new_records = by_id(now);

  std::vector<std::string> ids;
  for (const auto& [id, record] : old_records)
    ids.push_back(id);
  for (const auto& [id, record] : new_records)
    ids.push_back(id);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());

  for (const auto& id : ids) {
    const auto old_it = old_records.find(id);
    const auto new_it = new_records.find(id);
    const JobRecord* old_record = old_it == old_records.end() ? nullptr : old_it->second;
    const JobRecord* new_record = new_it == new_records.end() ? nullptr : new_it->second;
    const JobRecord& any = old_record ? *old_record : *new_record;

    JobComparison job;
    job.job_id = id;
    job.case_id = any.job.case_id;
    job.method = any.job.method_id;
    if (old_record)
      job.old_status = old_record->status;
    if (new_record)
      job.new_status = new_record->status;
    job.presence = !new_record   ? JobPresence::Missing
                   : !old_record ? JobPresence::New
                                 : JobPresence::Both;
    if (job.presence == JobPresence::Both) {
      job.changed_settings = changed_settings(old_record->job, new_record->job);
      for (const auto& name : metric_names_of(*old_record, *new_record)) {
        const double* o = old_record->metric(name);
        const double* n = new_record->metric(name);
        if (o && n) {
          job.metrics.push_back(judge(name, *o, *n, tolerances));
        } else {
          MetricChange m;
          m.metric = name;
          if (o)
            m.old_value = *o;
          if (n)
            m.new_value = *n;
          m.verdict = o ? MetricVerdict::Disappeared : MetricVerdict::Appeared;
          job.metrics.push_back(std::move(m));
        }
      }
    }
    comparison.jobs.push_back(std::move(job));
  }
  return comparison;
}

// --- Markdown -------------------------------------------------------------------------------

namespace {

std::string number(double value) {
  return fmt::format("{:.6g}", value);
}

std::string number(const std::optional<double>& value) {
  return value ? number(*value) : "-";
}

std::string relative_text(const MetricChange& m) {
  if (!m.old_value || !m.new_value)
    return "";
  if (m.from_zero)
    return "new from 0";
  if (std::isnan(m.relative_change))
    return "nan";
  return fmt::format("{:+.3g}%", 100.0 * m.relative_change);
}

struct Row {
  int rank = 0;  ///< regressions 0, improvements 1, other status changes 2, new 3, the rest 4
  std::string flag, job, metric, old_value, new_value, change, relative, allowed;
};

Row make_row(int rank, std::string flag, const std::string& job, std::string metric,
             std::string old_value, std::string new_value) {
  Row row;
  row.rank = rank;
  row.flag = std::move(flag);
  row.job = job;
  row.metric = std::move(metric);
  row.old_value = std::move(old_value);
  row.new_value = std::move(new_value);
  return row;
}

Row metric_row(int rank, const JobComparison& job, const MetricChange& m) {
  Row row = make_row(rank, to_string(m.verdict), job.job_id, m.metric, number(m.old_value),
                     number(m.new_value));
  if (m.old_value && m.new_value) {
    row.change = fmt::format("{:+.6g}", m.change);
    row.relative = relative_text(m);
    row.allowed = m.verdict == MetricVerdict::NotJudged ? "" : number(m.allowed);
  }
  return row;
}

std::vector<Row> comparison_rows(const Comparison& comparison) {
  std::vector<Row> rows;
  for (const auto& job : comparison.jobs) {
    const auto status = [](const std::optional<JobStatus>& s) {
      return s ? std::string(to_string(*s)) : std::string("-");
    };
    if (job.presence == JobPresence::Missing) {
      rows.push_back(
          make_row(0, "REGRESSION", job.job_id, "(job)", status(job.old_status), "missing"));
      continue;
    }
    if (job.presence == JobPresence::New) {
      rows.push_back(make_row(3, "new job", job.job_id, "(job)", "-", status(job.new_status)));
      continue;
    }
    if (job.status_changed()) {
      const bool better = *job.new_status == JobStatus::Ok;
      const int rank = job.status_regressed() ? 0 : better ? 1 : 2;
      const char* flag = rank == 0 ? "REGRESSION" : rank == 1 ? "improved" : "status changed";
      rows.push_back(make_row(rank, flag, job.job_id, "status", status(job.old_status),
                              status(job.new_status)));
    }
    for (const auto& m : job.metrics) {
      switch (m.verdict) {
        case MetricVerdict::Regressed:
          rows.push_back(metric_row(0, job, m));
          break;
        case MetricVerdict::Improved:
          rows.push_back(metric_row(1, job, m));
          break;
        case MetricVerdict::WithinTolerance:
          rows.push_back(metric_row(4, job, m));
          break;
        case MetricVerdict::Appeared:
        case MetricVerdict::Disappeared:
          // With a status change the metrics come and go with it; listed otherwise.
          if (!job.status_changed())
            rows.push_back(metric_row(4, job, m));
          break;
        case MetricVerdict::Unchanged:
        case MetricVerdict::NotJudged:
          break;
      }
    }
  }
  // Jobs are sorted by id and metrics by name already; a stable sort by rank keeps that.
  std::stable_sort(rows.begin(), rows.end(),
                   [](const Row& a, const Row& b) { return a.rank < b.rank; });
  return rows;
}

}  // namespace

namespace {

// Which methods ran with other settings, and which settings: one line per method, with the
// number of jobs; empty when none did.
std::string settings_paragraph(const Comparison& comparison) {
  std::map<std::string, std::pair<std::size_t, std::set<std::string>>> by_method;
  for (const auto& job : comparison.jobs) {
    if (job.changed_settings.empty())
      continue;
    auto& [jobs, settings] = by_method[job.method];
    ++jobs;
    settings.insert(job.changed_settings.begin(), job.changed_settings.end());
  }
  if (by_method.empty())
    return "";
  std::string out = "Method settings differ (the same jobs ran with other settings; not judged):\n";
  for (const auto& [method, entry] : by_method) {
    out += fmt::format("- {} ({} jobs): ", method, entry.first);
    std::string list;
    for (const auto& setting : entry.second)
      list += (list.empty() ? "" : "; ") + setting;
    out += list + "\n";
  }
  return out + "\n";
}

}  // namespace

std::string format_comparison(const Comparison& comparison) {
  std::string out;
  out += fmt::format("Comparing {} (new) against {} (baseline)\n\n",
                     comparison.new_label.empty() ? "?" : comparison.new_label,
                     comparison.base_label.empty() ? "?" : comparison.base_label);
  const auto rows = comparison_rows(comparison);
  const std::string settings = settings_paragraph(comparison);
  if (rows.empty() && settings.empty()) {
    out += "No changes.\n\n";
  } else if (rows.empty()) {
    out += "No metric or status changes.\n\n";
  } else {
    out += "| verdict | job | metric | old | new | change | relative | allowed |\n";
    out += "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: |\n";
    for (const auto& r : rows) {
      out += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", r.flag,
                         markdown_cell(r.job), markdown_cell(r.metric), r.old_value, r.new_value,
                         r.change, r.relative, r.allowed);
    }
    out += "\n";
  }
  out += settings;

  std::size_t compared = 0, missing = 0, added = 0, status_regressions = 0;
  std::size_t metric_regressions = 0, improvements = 0, within = 0;
  for (const auto& job : comparison.jobs) {
    if (job.presence == JobPresence::Missing)
      ++missing;
    if (job.presence == JobPresence::New)
      ++added;
    if (job.presence != JobPresence::Both)
      continue;
    ++compared;
    if (job.status_regressed())
      ++status_regressions;
    for (const auto& m : job.metrics) {
      if (m.verdict == MetricVerdict::Regressed)
        ++metric_regressions;
      if (m.verdict == MetricVerdict::Improved)
        ++improvements;
      if (m.verdict == MetricVerdict::WithinTolerance)
        ++within;
    }
  }
  out += fmt::format(
      "{} jobs compared, {} missing, {} new; {} regressed jobs ({} status, {} metrics), {} "
      "improved metrics, {} changed within tolerance: {}\n",
      compared, missing, added, comparison.regressed_jobs(), status_regressions, metric_regressions,
      improvements, within, comparison.has_regression() ? "REGRESSION" : "OK");
  return out;
}

void print_comparison(const Comparison& comparison, std::FILE* out) {
  const auto text = format_comparison(comparison);
  std::fwrite(text.data(), 1, text.size(), out);
  std::fflush(out);
}

// --- JUnit XML ------------------------------------------------------------------------------

namespace {

std::string metric_line(const MetricChange& m) {
  return fmt::format("{}: {} -> {} (change {:+.6g}, {}, allowed {})", m.metric, number(m.old_value),
                     number(m.new_value), m.change, relative_text(m), number(m.allowed));
}

}  // namespace

void write_junit_xml(const Comparison& comparison, const std::filesystem::path& path) {
  std::map<std::string, std::vector<const JobComparison*>> by_method;
  for (const auto& job : comparison.jobs)
    by_method[job.method].push_back(&job);

  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml += fmt::format("<testsuites name=\"holebench compare\" tests=\"{}\" failures=\"{}\">\n",
                     comparison.jobs.size(), comparison.regressed_jobs());
  for (const auto& [method, jobs] : by_method) {
    const auto failures = std::count_if(jobs.begin(), jobs.end(),
                                        [](const JobComparison* j) { return j->regression(); });
    xml += fmt::format(
        "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" skipped=\"0\">\n",
        xml_escape(method, true), jobs.size(), failures);
    for (const JobComparison* job : jobs) {
      xml += fmt::format("    <testcase classname=\"{}\" name=\"{}\"", xml_escape(method, true),
                         xml_escape(job->job_id, true));
      std::string message, text, out;
      if (job->presence == JobPresence::Missing) {
        message = "missing in the new results";
        text = fmt::format("the baseline has this job (status {}); the new results do not",
                           to_string(*job->old_status));
      } else if (job->regression()) {
        const auto regressed = job->regressed_metrics();
        if (job->status_regressed()) {
          message = fmt::format("status {} -> {}", to_string(*job->old_status),
                                to_string(*job->new_status));
          text = message + "\n";
        }
        if (!regressed.empty()) {
          message += fmt::format("{}{} regressed metric{}", message.empty() ? "" : "; ",
                                 regressed.size(), regressed.size() == 1 ? "" : "s");
        }
        for (const MetricChange* m : regressed)
          text += metric_line(*m) + "\n";
      } else if (job->presence == JobPresence::New) {
        out = fmt::format("new job (status {}): no baseline to compare with",
                          to_string(*job->new_status));
      }
      if (message.empty() && out.empty()) {
        xml += "/>\n";
        continue;
      }
      xml += ">\n";
      if (!message.empty()) {
        xml += fmt::format("      <failure type=\"regression\" message=\"{}\">{}</failure>\n",
                           xml_escape(message, true), xml_escape(text, false));
      }
      if (!out.empty())
        xml += fmt::format("      <system-out>{}</system-out>\n", xml_escape(out, false));
      xml += "    </testcase>\n";
    }
    xml += "  </testsuite>\n";
  }
  xml += "</testsuites>\n";

  if (path.has_parent_path())
    std::filesystem::create_directories(path.parent_path());
  std::ofstream file(path, std::ios::binary);
  if (!file)
    throw std::runtime_error(path.string() + ": cannot write the JUnit report");
  file << xml;
  if (!file)
    throw std::runtime_error(path.string() + ": cannot write the JUnit report");
}

}  // namespace holebench::harness
