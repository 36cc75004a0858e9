// The anatomical structures with laterality that findings refer to.
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz {
namespace {

using test::shippedAnatomy;

TEST(AnatomyCatalogTest, DermatomesC2ToS5OnBothSides) {
  const AnatomyCatalog& anatomy = shippedAnatomy();
  std::vector<std::string> expected;
  for (int i = 2; i <= 8; ++i) expected.push_back("dermatome_C" + std::to_string(i));
  for (int i = 1; i <= 12; ++i) expected.push_back("dermatome_T" + std::to_string(i));
  for (int i = 1; i <= 5; ++i) expected.push_back("dermatome_L" + std::to_string(i));
  for (int i = 1; i <= 5; ++i) expected.push_back("dermatome_S" + std::to_string(i));
  std::size_t dermatomes = 0;
  for (const auto& structure : anatomy.structures())
    dermatomes += structure.class_id == "dermatome";
  EXPECT_EQ(dermatomes, 29u);
  for (const auto& id : expected) {
    const Structure* structure = anatomy.structure(id);
    ASSERT_NE(structure, nullptr) << id;
    EXPECT_TRUE(anatomy.sideAllowed(*structure, Side::kLeft));
    EXPECT_TRUE(anatomy.sideAllowed(*structure, Side::kRight));
    EXPECT_FALSE(anatomy.sideAllowed(*structure, Side::kNone));
  }
  EXPECT_EQ(anatomy.structure("dermatome_C1"), nullptr);
  EXPECT_EQ(anatomy.displayName(*anatomy.structure("dermatome_L5"), Side::kLeft),
            "Dermatome L5 (left)");
}

TEST(AnatomyCatalogTest, MusclesCarryTheirFmaIds) {
  const AnatomyCatalog& anatomy = shippedAnatomy();
  for (const auto& structure : anatomy.structures()) {
    if (structure.class_id == "muscle") {
      EXPECT_FALSE(structure.fma_id.empty()) << structure.id;
    }
  }
  EXPECT_EQ(anatomy.structure("extensor_hallucis_longus")->fma_id, "FMA:22533");
  EXPECT_EQ(anatomy.structure("tibialis_anterior")->fma_id, "FMA:22532");
  EXPECT_EQ(anatomy.structureByFmaId("FMA:22541")->id, "gastrocnemius");
}

TEST(AnatomyCatalogTest, SmallStructuresNeedProxiesAndMidlineHasNoSide) {
  const AnatomyCatalog& anatomy = shippedAnatomy();
  for (const char* id :
       {"patellar_ligament", "calcaneal_tendon", "urethra", "external_anal_sphincter"}) {
    EXPECT_TRUE(anatomy.classOf(*anatomy.structure(id)).proxy) << id;
  }
  EXPECT_FALSE(anatomy.classOf(*anatomy.structure("dermatome_L5")).proxy);
  EXPECT_FALSE(anatomy.classOf(*anatomy.structure("tibialis_anterior")).proxy);
  const Structure& urethra = *anatomy.structure("urethra");
  EXPECT_TRUE(anatomy.sideAllowed(urethra, Side::kNone));
  EXPECT_FALSE(anatomy.sideAllowed(urethra, Side::kLeft));
  EXPECT_EQ(anatomy.displayName(urethra, Side::kNone), "Urethra");
}

TEST(AnatomyCatalogTest, SidesParseAndMirror) {
  EXPECT_EQ(sideFromString("left"), Side::kLeft);
  EXPECT_EQ(sideFromString("none"), Side::kNone);
  EXPECT_FALSE(sideFromString("links").has_value());
  EXPECT_EQ(contralateral(Side::kLeft), Side::kRight);
  EXPECT_EQ(contralateral(Side::kNone), Side::kNone);
}

void expectCatalogError(const std::string& yaml, const std::string& fragment) {
  try {
    AnatomyCatalog::fromYamlText(yaml, "anatomy.yaml");
    FAIL() << "accepted: " << yaml;
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(AnatomyCatalogTest, InvalidCataloguesAreRejectedWithTheEntry) {
  const std::string classes =
      "structure_classes:\n"
      "  - {id: muscle, laterality: bilateral, requires_fma_id: true}\n";
  expectCatalogError(classes + "structures:\n  - {id: soleus, class: muscle, name: M. soleus}\n",
                     "structure 'soleus' (muscle) needs an fma_id");
  expectCatalogError(classes +
                         "structures:\n"
                         "  - {id: a, class: muscle, name: A, fma_id: 'FMA:1'}\n"
                         "  - {id: a, class: muscle, name: B, fma_id: 'FMA:2'}\n",
                     "structure 'a' is defined twice");
  expectCatalogError(classes + "structures:\n  - {id: a, class: bone, name: A}\n",
                     "unknown class 'bone'");
  expectCatalogError(classes + "structures:\n  - {id: a, class: muscle, name: A, fma: 'FMA:1'}\n",
                     "unknown key 'fma'");
  expectCatalogError("structure_classes: [\n", "anatomy.yaml:");
}

}  // namespace
}  // namespace vicc_anatomy_viz
