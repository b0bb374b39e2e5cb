// What an instructor's launch shows: the class report and the gradebook of the stored
// submissions, and a regrade with a new bank.
#pragma once

#include <string>
#include <vector>

#include "serve/catalog.h"
#include "serve/store.h"

namespace raygrade::serve {

// The last submission of each student (by sub), in the order of their first submission.
std::vector<SubmissionRecord> last_per_student(const std::vector<SubmissionRecord>& all);

// The class list a report and a gradebook are of: the platform's roster as last read (NRPS), and
// what to say about it. Enrolled are its learners whose status is Active or Inactive (an
// Inactive one is marked); a Deleted member left the course and is listed only by a submission.
struct ClassList {
  std::string issuer;  // the platform whose user_ids the members' are
  std::vector<Member> members;
  std::string note;  // said at the top of the report ("" nothing)
};

// The class report's page (reports/class_report.h) over each student's last submission, graded
// again as its student's variant with full feedback; the enrolled learners without a
// submission listed apart.
std::string class_report_page(const CatalogEntry& entry, const std::vector<SubmissionRecord>& all,
                              const ClassList& list = {});

// The gradebook (`raygrade grade --format csv` of each student's last submission): a row per
// enrolled learner in the roster's order (0 points and "no submission" for one who handed in
// nothing), then one per other student who submitted.
std::string gradebook_of(const CatalogEntry& entry, const std::vector<SubmissionRecord>& all,
                         const ClassList& list = {});

struct Regraded {
  std::string sub;
  double before = 0;
  double after = 0;
  double max_score = 0;
};

// A bank file sent for a regrade: its name and text.
struct BankFile {
  std::string name;
  std::string text;
};

// Each student's last submission graded with `bank` (the files of a bank, kept in a new folder
// of DIR/banks/) in place of the assignment's bank: the students whose score it changes.
// Throws Refusal (400) when the bank cannot be read or lacks a problem of the assignment.
std::vector<Regraded> regrade_with(const CatalogEntry& entry,
                                   const std::vector<SubmissionRecord>& all,
                                   const std::vector<BankFile>& bank, const std::string& data_dir);

}  // namespace raygrade::serve
