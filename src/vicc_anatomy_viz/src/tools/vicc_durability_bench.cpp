// vicc_durability_bench: what PRAGMA synchronous = FULL costs against NORMAL in the record
// store's WAL mode, for bench/patient_status/durability.md. Times (a) single-examination
// write transactions, one commit each, as `vicc_patient record` makes them, and (b) one bulk
// import transaction, on fresh databases with the VICC schema; the two settings alternate
// between repetitions so that load changes on the machine hit both alike.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/schema_migrations.hpp"
#include "vicc_anatomy_viz/sqlite_connection.hpp"
#include "vicc_common/command_line.hpp"

namespace {

using vicc_anatomy_viz::SqliteConnection;
using vicc_anatomy_viz::SqliteStatement;
using vicc_anatomy_viz::SqliteTransaction;
using Clock = std::chrono::steady_clock;

constexpr int kFindingsPerExamination = 12;  // a typical examination of the sample data

/// Writes examinations with their findings and two values each, the rows RecordStore writes.
class ExaminationWriter {
 public:
  explicit ExaminationWriter(SqliteConnection& connection)
      : connection_(connection),
        patient_(connection, "INSERT INTO patients (pseudonym, created_at) VALUES (?, 0)"),
        examination_(connection,
                     "INSERT INTO examinations (patient_id, taken_at, view_id, source, "
                     "recorded_at) VALUES (?, ?, 'neurological_status_sdh', 'json', 0)"),
        finding_(connection,
                 "INSERT INTO findings (examination_id, category, structure, side) "
                 "VALUES (?, 'radicular_pain', ?, 'left')"),
        value_(connection,
               "INSERT INTO finding_values (finding_id, prop_type, int_value, text_value) "
               "VALUES (?, ?, ?, NULL)") {}

  void write(int number) {
    run(patient_.bind(1, "BENCH-" + std::to_string(number)));
    run(examination_.bind(1, connection_.lastInsertRowid()).bind(2, 1678094100 + number));
    const std::int64_t examination_row = connection_.lastInsertRowid();
    for (int f = 0; f < kFindingsPerExamination; ++f) {
      run(finding_.bind(1, examination_row).bind(2, "structure_" + std::to_string(f)));
      const std::int64_t finding_row = connection_.lastInsertRowid();
      run(value_.bind(1, finding_row).bind(2, "intensity").bind(3, f % 11));
      run(value_.bind(1, finding_row).bind(2, "quality").bind(3, f % 3));
    }
  }

 private:
  static void run(SqliteStatement& statement) {
    statement.step();
    statement.reset();
  }
  SqliteConnection& connection_;
  SqliteStatement patient_, examination_, finding_, value_;
};

/// A fresh database with the record store's settings but `synchronous`.
void openFresh(const std::string& path, const std::string& synchronous,
               std::unique_ptr<SqliteConnection>& connection) {
  connection.reset();
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
  connection =
      std::make_unique<SqliteConnection>(path, 5000, SqliteConnection::OpenMode::kCreateReadWrite);
  connection->exec("PRAGMA journal_mode = WAL");
  connection->exec("PRAGMA foreign_keys = ON");
  connection->exec("PRAGMA synchronous = " + synchronous);
  vicc_anatomy_viz::migrateSchema(*connection);
}

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// Median milliseconds of one single-examination transaction.
double singleTransactionMs(SqliteConnection& connection, int records) {
  ExaminationWriter writer(connection);
  std::vector<double> times;
  for (int i = 0; i < records; ++i) {
    const auto start = Clock::now();
    SqliteTransaction transaction(connection);
    writer.write(i);
    transaction.commit();
    times.push_back(millisecondsSince(start));
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

/// Milliseconds of one transaction with `examinations` examinations.
double bulkImportMs(SqliteConnection& connection, int examinations) {
  ExaminationWriter writer(connection);
  const auto start = Clock::now();
  SqliteTransaction transaction(connection);
  for (int i = 0; i < examinations; ++i) writer.write(i);
  transaction.commit();
  return millisecondsSince(start);
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

namespace cli = vicc_common::cli;

const std::vector<cli::OptionSpec> kOptionSpecs = {
    {"dir", "DIR", "where the databases are written: on the disk to measure, not tmpfs"},
    {"records", "N", "single-examination transactions per repetition (default 200)"},
    {"bulk", "M", "examinations in the bulk import transaction (default 2000)"},
    {"repeat", "R", "repetitions, the two settings alternating (default 5)"},
};

std::string usage() {
  return cli::helpText("vicc_durability_bench --dir DIR [--records N] [--bulk M] [--repeat R]",
                       "Times PRAGMA synchronous = FULL against NORMAL (CSV on stdout).\n"
                       "Exit code 0 on success, 1 on error, 2 on a usage error.",
                       kOptionSpecs);
}

struct Options {
  std::string directory;
  int records = 200, bulk = 2000, repeat = 5;
};

/// Throws cli::UsageError naming what is wrong.
Options parseOptions(const std::vector<std::string>& args) {
  const cli::ParsedArguments parsed = cli::parseArguments(args, kOptionSpecs);
  if (!parsed.positional.empty()) {
    throw cli::UsageError("unexpected argument '" + parsed.positional.front() + "'");
  }
  Options options;
  options.directory = parsed.required("dir", "vicc_durability_bench");
  options.records = parsed.integer("records", options.records, 1, 10000000);
  options.bulk = parsed.integer("bulk", options.bulk, 1, 10000000);
  options.repeat = parsed.integer("repeat", options.repeat, 1, 10000);
  return options;
}

int run(const Options& options) {
  const int records = options.records, bulk = options.bulk, repeat = options.repeat;
  const std::string path = options.directory + "/durability_bench.db";
  std::unique_ptr<SqliteConnection> connection;
  const std::vector<std::string> settings = {"NORMAL", "FULL"};
  std::vector<std::vector<double>> single(settings.size()), imports(settings.size());
  for (int r = 0; r < repeat; ++r) {
    for (std::size_t s = 0; s < settings.size(); ++s) {
      openFresh(path, settings[s], connection);
      single[s].push_back(singleTransactionMs(*connection, records));
      openFresh(path, settings[s], connection);
      imports[s].push_back(bulkImportMs(*connection, bulk));
    }
  }
  connection.reset();
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
  std::printf("synchronous,record_ms_median,bulk_import_ms_median,records,bulk,repeat\n");
  for (std::size_t s = 0; s < settings.size(); ++s) {
    std::printf("%s,%.3f,%.1f,%d,%d,%d\n", settings[s].c_str(), median(single[s]),
                median(imports[s]), records, bulk, repeat);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::runTool(
      "vicc_durability_bench", argc, argv, usage(),
      [](const std::vector<std::string>& arguments) { return run(parseOptions(arguments)); });
}
