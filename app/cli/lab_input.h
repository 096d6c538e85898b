#pragma once

// How the lab commands read their CSV input: the whole file through core's
// reader, then the parser; a CsvError or a refusal (std::invalid_argument,
// e.g. a gauge smaller than the touches) becomes a message starting with the
// file's path.

#include <stdexcept>
#include <string>

#include "core/common/csv_reader.h"
#include "core/common/file_io.h"

namespace probecycle::cli {

template <typename Parse>
auto read_lab_csv(const std::string& path, Parse parse) {
    const std::string text = read_text_file(path);
    try {
        return parse(text);
    } catch (const CsvError& e) {
        throw std::runtime_error(path + ": " + e.what());
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}

}  // namespace probecycle::cli
