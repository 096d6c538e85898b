// The window's project file: parse and write back. Any input either is
// refused with a ProjectError (whose messages are built, as the window shows
// them) or writes a file that reads back to the same text.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/project/project_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace probecycle;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    (void)is_project_text(text);
    Project project;
    try {
        project = parse_project(text);
    } catch (const ProjectError& e) {
        for (const FieldError& error : e.errors()) (void)error.message();
        return 0;
    }
    const std::string written = project_json(project);
    if (project_json(parse_project(written)) != written) std::abort();
    return 0;
}
