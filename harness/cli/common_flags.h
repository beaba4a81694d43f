// Flags and validators more than one subcommand shares.
#pragma once

#include "generators/case_catalog.h"

#include <CLI/CLI.hpp>

#include <exception>
#include <string>

namespace holebench::harness::cli {

/// --mesh, --brep-deflection, --no-cad and --cad-dir: the cases a catalog lists.
void add_catalog_flags(CLI::App* command, generators::CatalogOptions& catalog, bool& no_cad);

/// A CLI11 validator from a parser that throws std::invalid_argument with the message.
template <typename Parse>
CLI::Validator parsed_by(Parse parse, const std::string& name) {
  return CLI::Validator(
      [parse](std::string& text) {
        try {
          parse(text);
          return std::string();
        } catch (const std::exception& e) {
          return std::string(e.what());
        }
      },
      "", name);
}

}  // namespace holebench::harness::cli
