#pragma once
// The versioned schema of the patient database. PRAGMA user_version holds the version,
// PRAGMA application_id marks the file as ours; migrations run in order, each atomically.

#include <cstdint>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/sqlite_connection.hpp"

namespace vicc_anatomy_viz {

/// "VICC" in ASCII: tells our databases from any other SQLite file.
constexpr std::int32_t kApplicationId = 0x56494343;

struct Migration {
  int version;               ///< user_version after this migration
  std::string description;
  std::string sql;
};

const std::vector<Migration>& schemaMigrations();
int latestSchemaVersion();

/// Checks that the file is ours (or empty) and brings it to `target_version` (default: the
/// latest). Throws StoreError kForeign for another application's database, kNewerSchema for
/// a file written by a newer version.
void migrateSchema(SqliteConnection& connection, int target_version = -1);

}  // namespace vicc_anatomy_viz
