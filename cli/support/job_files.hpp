// The job descriptions a run reads (docs/job-files.md): the one a generated deck was made with
// (--cut, --html's design), the press-feeder job (--press-proof) and the tapping job
// (--thread-proof). Each throws DeckError naming the file.
#pragma once

#include "cli/support/deck_files.hpp"

#include "decks/job_file.hpp"
#include "decks/press_feeder_job.hpp"
#include "decks/tapping_job.hpp"

#include <string>

namespace parsons::cli {

// The job description of a generated deck; refused when it was written for another deck.
decks::JobDescription read_job(const std::string& file, const std::string& deck_path,
                               const DeckFlags& deck_flags);

// The job file for --press-proof.
decks::PressFeederJob read_press_job(const std::string& file);

// The job file for --thread-proof.
decks::TappingJob read_tapping_job(const std::string& file);

} // namespace parsons::cli
