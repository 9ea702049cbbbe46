// Editing materials: a new material goes first (every surface can use it) with every reference
// moved along; a surface's material and a material's look change as the reader allows, and a
// refused edit leaves the document as it was with the reader's words.
#include "model/edit/edit.hpp"

#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace {

using sweep::Document;
using sweep::EditError;

using sweep::test::edit_error;

const char* const kTorus = "circ c 16 1\ncirc s 32 3\ngcyl t c s\n";

TEST(EditMaterial, ANewMaterialGoesFirstAndEveryReferenceFollows) {
  Document doc = sweep::io::parse_swp(kTorus, "t.swp");
  EXPECT_EQ(sweep::add_material(doc, "clay"), 0);
  ASSERT_EQ(doc.objects.size(), 4u);
  EXPECT_EQ(doc.objects[0].kind(), sweep::ObjectKind::Material);
  EXPECT_EQ(doc.objects[3].as<sweep::ProfilePart>().profile, 1);
  EXPECT_EQ(doc.objects[3].as<sweep::CylinderSurface>().sweep, 2);
  sweep::set_surface_material(doc, 3, 0);
  EXPECT_EQ(doc.objects[3].as<sweep::MaterialPart>().material, 0);
  // Saved, it reads back the same, with the material line first and the clause on the surface.
  const std::string text = sweep::io::write_swp(doc);
  EXPECT_EQ(text.rfind("material clay\n", 0), 0u) << text;
  EXPECT_NE(text.find("gcyl t c s material clay\n"), std::string::npos) << text;
  EXPECT_EQ(sweep::io::parse_swp(text, "t.swp"), doc);
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_material(doc, "t"); }), "name 't' is already used by another object");
}

TEST(EditMaterial, ALookIsCheckedAsTheReaderChecksIt) {
  Document doc = sweep::io::parse_swp(std::string("material m\n") + kTorus, "t.swp");
  sweep::Object look = doc.objects[0];
  look.as<sweep::MaterialLook>().color = glm::dvec3(0.2, 0.4, 0.6);
  look.as<sweep::MaterialLook>().shininess = 90.0;
  look.as<sweep::MaterialLook>().checker = 8;
  sweep::set_material_look(doc, 0, look, ".");
  EXPECT_EQ(doc.objects[0].as<sweep::MaterialLook>().color, glm::dvec3(0.2, 0.4, 0.6));
  EXPECT_EQ(doc.objects[0].as<sweep::MaterialLook>().checker, 8);
  sweep::Object bad = look;
  bad.as<sweep::MaterialLook>().color.y = 1.5;
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_material_look(doc, 0, bad, "."); }),
            "material 'm': colour components must be from 0 to 1");
  bad = look;
  bad.as<sweep::MaterialLook>().texture = "nope.png";
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_material_look(doc, 0, bad, "/tmp"); }),
            "material 'm': a material has a texture or a checker, not both");
  bad.as<sweep::MaterialLook>().checker = 0;
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_material_look(doc, 0, bad, "/nowhere"); }),
            "material 'm': cannot open /nowhere/nope.png: no such file");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_surface_material(doc, 3, 1); }), "'c' is not a material");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_surface_material(doc, 1, 0); }),
            "'c' is not a surface: it takes no material");
}

TEST(EditMaterial, DeletingAnObjectAboveKeepsEveryReferenceRight) {
  // An unused curve above the material, the cage and the surfaces that use them: after deleting
  // it every reference (profile, sweep, material, subd source) still names the same object.
  Document doc =
      sweep::io::parse_swp("circ unused 8 1\nmaterial m checker 2\n" + std::string(kTorus) +
                               "mesh cage 3 1 [0 0 0] [1 0 0] [0 1 0] [0 1 2]\nsubd smooth 1 cage material m\n",
                           "t.swp");
  sweep::set_surface_material(doc, 4, 1);
  sweep::delete_object(doc, 0);
  EXPECT_NO_THROW(sweep::io::validate_document(doc));
  const std::string text = sweep::io::write_swp(doc);
  EXPECT_NE(text.find("gcyl t c s material m\n"), std::string::npos) << text;
  EXPECT_NE(text.find("subd smooth 1 cage material m\n"), std::string::npos) << text;
  ASSERT_EQ(doc.objects[5].name, "smooth");
  EXPECT_EQ(doc.objects[5].as<sweep::SubdivisionSurface>().source, 4);
  EXPECT_EQ(doc.objects[5].as<sweep::MaterialPart>().material, 0);
  EXPECT_EQ(doc.objects[3].as<sweep::MaterialPart>().material, 0);
}

TEST(EditMaterial, AMaterialInUseCannotBeDeleted) {
  Document doc = sweep::io::parse_swp(std::string("material m\n") + kTorus + "\n", "t.swp");
  sweep::set_surface_material(doc, 3, 0);
  const std::string message = edit_error(doc, [&] { sweep::delete_object(doc, 0); });
  EXPECT_NE(message.find("'t'"), std::string::npos) << message;
}

}  // namespace
