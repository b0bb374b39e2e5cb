// The table of subcommands.
#include "cli/command.h"

namespace raygrade::cli {

Runner setup_solve(CLI::App& sub);
Runner setup_run(CLI::App& sub);
Runner setup_solutions(CLI::App& sub);
Runner setup_bench(CLI::App& sub);
Runner setup_grade(CLI::App& sub);
Runner setup_check(CLI::App& sub);
Runner setup_generate(CLI::App& sub);
Runner setup_handout(CLI::App& sub);
Runner setup_export(CLI::App& sub);
Runner setup_schema(CLI::App& sub);
Runner setup_tables(CLI::App& sub);
Runner setup_report(CLI::App& sub);
Runner setup_regrade(CLI::App& sub);
Runner setup_read_typed(CLI::App& sub);
#ifdef RAYGRADE_HAS_SERVE
Runner setup_serve(CLI::App& sub);
#endif

const std::vector<Command>& command_table() {
  static const std::vector<Command> table = {
      {"run", "the main job: solve the bank, write worked solutions, grade submissions",
       &setup_run},
      {"grade", "grade submissions, for a person, a gradebook or an LMS (--format)", &setup_grade},
      {"report", "what a class got wrong, and why: report.html and report.json (--out)",
       &setup_report},
      {"regrade", "which students' points or feedback a new bank changes, writing nothing",
       &setup_regrade},
      {"solve", "print the reference answers (and worked solutions) of problems", &setup_solve},
      {"solutions", "write (or --check) the worked solutions of a bank, one file per problem",
       &setup_solutions},
      {"bench", "time and judge every intersection formula against MPFR truth", &setup_bench},
      {"check", "validate a problem bank: stated answers, ill-posed problems, self-tests",
       &setup_check},
      {"generate", "seeded problem variants with nice numbers, and their solutions",
       &setup_generate},
      {"handout", "each student's problems as a page with answer inputs, and a template",
       &setup_handout},
      {"export", "an assignment packaged for a learning platform (its help lists them)",
       &setup_export},
      {"schema", "the problem schema, from the list of primitives (docs/problem.schema.json)",
       &setup_schema},
      {"tables", "the docs' tables of primitives, kinds and formats, from the code's own",
       &setup_tables},
      {"read-typed", "typed answer boxes read as the grader reads them (for tests)",
       &setup_read_typed},
#ifdef RAYGRADE_HAS_SERVE
      {"serve", "an LTI 1.3 tool: students launch, submit and get graded from any LMS",
       &setup_serve},
#endif
  };
  return table;
}

}  // namespace raygrade::cli
