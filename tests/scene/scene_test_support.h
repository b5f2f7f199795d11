#pragma once

#include "apcs/formats/dat_file.h"
#include "apcs/scene/scene_file.h"

#include <catch2/catch.hpp>

#include <map>
#include <string>

namespace apcs::test {

// .dat files held in memory, read by name: a scene without a folder.
struct DatFiles {
    std::map<std::string, std::string> texts;

    SceneFileReader reader() const
    {
        return [this](const std::string& name) -> Expected<DatFile> {
            const auto found = texts.find(name);
            if (found == texts.end())
                return Diagnostic{name, 0, "no such file"};
            return parse_dat(found->second, name, 1);
        };
    }
};

inline Scene scene_from(const std::string& text, const DatFiles& files, const StaffValues& staff = {})
{
    Expected<Scene> scene = parse_scene(text, "t.scn", files.reader(), staff);
    INFO((scene ? std::string() : scene.error().to_string()));
    REQUIRE(scene.has_value());
    return std::move(*scene);
}

} // namespace apcs::test
