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
  int version;  ///< user_version after this migration
  std::string description;
  std::string sql;
};

const std::vector<Migration>& schemaMigrations();
int latestSchemaVersion();

/// Reads only: throws StoreError kForeign when the file is another application's database,
/// kNewerSchema when a newer version of ours wrote it, kCorrupt when it is not SQLite at all.
void checkDatabaseIdentity(SqliteConnection& connection);

/// Checks the identity, then brings the schema to `target_version` (default: the latest),
/// one transaction per migration.
void migrateSchema(SqliteConnection& connection, int target_version = -1);

}  // namespace vicc_anatomy_viz
