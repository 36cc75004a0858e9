#include "vicc_anatomy_viz/schema_migrations.hpp"

#include <cstdio>

#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz {

const std::vector<Migration>& schemaMigrations() {
  static const std::vector<Migration> migrations = {
      {1, "patients, examinations, findings and their values",
       "PRAGMA application_id = " + std::to_string(kApplicationId) +
           ";\n"
           "CREATE TABLE patients (\n"
           "  id INTEGER PRIMARY KEY,\n"
           "  pseudonym TEXT NOT NULL UNIQUE,\n"
           "  created_at INTEGER NOT NULL);\n"
           "CREATE TABLE examinations (\n"
           "  id INTEGER PRIMARY KEY,\n"
           "  patient_id INTEGER NOT NULL REFERENCES patients(id) ON DELETE CASCADE,\n"
           "  taken_at INTEGER NOT NULL,\n"
           "  view_id TEXT NOT NULL,\n"
           "  UNIQUE (patient_id, taken_at));\n"
           "CREATE TABLE findings (\n"
           "  id INTEGER PRIMARY KEY,\n"
           "  examination_id INTEGER NOT NULL REFERENCES examinations(id) ON DELETE CASCADE,\n"
           "  category TEXT NOT NULL,\n"
           "  structure TEXT NOT NULL,\n"
           "  side TEXT NOT NULL CHECK (side IN ('left', 'right', 'none')),\n"
           "  UNIQUE (examination_id, category, structure, side));\n"
           "CREATE TABLE finding_values (\n"
           "  finding_id INTEGER NOT NULL REFERENCES findings(id) ON DELETE CASCADE,\n"
           "  prop_type TEXT NOT NULL,\n"
           "  int_value INTEGER,\n"
           "  text_value TEXT,\n"
           "  CHECK ((int_value IS NULL) <> (text_value IS NULL)),\n"
           "  PRIMARY KEY (finding_id, prop_type)) WITHOUT ROWID;\n"},
      {2, "provenance of examinations (source format and time of writing)",
       "ALTER TABLE examinations ADD COLUMN source TEXT NOT NULL DEFAULT 'unknown';\n"
       "ALTER TABLE examinations ADD COLUMN recorded_at INTEGER NOT NULL DEFAULT 0;\n"},
      {3,
       "microsecond examination times, preliminary and partial examinations, superseded "
       "versions kept as history",
       "UPDATE examinations SET taken_at = taken_at * 1000000;\n"
       "ALTER TABLE examinations ADD COLUMN status TEXT NOT NULL DEFAULT 'final'\n"
       "  CHECK (status IN ('final', 'preliminary'));\n"
       "ALTER TABLE examinations ADD COLUMN partial INTEGER NOT NULL DEFAULT 0\n"
       "  CHECK (partial IN (0, 1));\n"
       "ALTER TABLE examinations ADD COLUMN partial_reason TEXT NOT NULL DEFAULT '';\n"
       "CREATE TABLE superseded_examinations (\n"
       "  id INTEGER PRIMARY KEY,\n"
       "  patient_id INTEGER NOT NULL REFERENCES patients(id) ON DELETE CASCADE,\n"
       "  taken_at INTEGER NOT NULL,\n"
       "  recorded_at INTEGER NOT NULL,\n"
       "  superseded_at INTEGER NOT NULL,\n"
       "  replaced_by_source TEXT NOT NULL,\n"
       "  record TEXT NOT NULL);\n"
       "CREATE INDEX superseded_by_time ON superseded_examinations (patient_id, taken_at);\n"},
  };
  return migrations;
}

int latestSchemaVersion() { return schemaMigrations().back().version; }

void checkDatabaseIdentity(SqliteConnection& connection) {
  const std::int64_t application_id = connection.queryInt("PRAGMA application_id");
  const std::int64_t version = connection.queryInt("PRAGMA user_version");
  const std::int64_t tables = connection.queryInt(
      "SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name NOT LIKE 'sqlite_%'");
  if (application_id != kApplicationId && (application_id != 0 || version != 0 || tables > 0)) {
    char id[16];
    std::snprintf(id, sizeof(id), "0x%08llx",
                  static_cast<unsigned long long>(application_id & 0xffffffffLL));
    throw StoreError(StoreError::Kind::kForeign,
                     "'" + connection.path() +
                         "' is an SQLite database of another application, not a VICC patient "
                         "database (application_id " +
                         id + ", " + std::to_string(tables) + " tables); it was left untouched");
  }
  if (version > latestSchemaVersion()) {
    throw StoreError(StoreError::Kind::kNewerSchema,
                     "patient database '" + connection.path() + "' has schema version " +
                         std::to_string(version) + ", newer than this program's " +
                         std::to_string(latestSchemaVersion()) + "; update the software");
  }
}

void migrateSchema(SqliteConnection& connection, int target_version) {
  checkDatabaseIdentity(connection);
  if (target_version < 0) target_version = latestSchemaVersion();
  // Up to date: no write lock needed, so readers open the file while another process writes.
  if (connection.queryInt("PRAGMA user_version") >= target_version) return;
  for (const auto& migration : schemaMigrations()) {
    if (migration.version > target_version) break;
    SqliteTransaction transaction(connection);
    // Re-read under the write lock: another process may have migrated meanwhile.
    if (connection.queryInt("PRAGMA user_version") >= migration.version) {
      transaction.commit();
      continue;
    }
    connection.exec(migration.sql);
    connection.exec("PRAGMA user_version = " + std::to_string(migration.version));
    transaction.commit();
  }
}

}  // namespace vicc_anatomy_viz
