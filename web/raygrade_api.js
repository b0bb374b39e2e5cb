// raygrade.js's API, appended to the module Emscripten writes (--post-js): createRaygrade()
// resolves to the module, which then has solve, grade and solution. Inputs are JSON texts; a
// set of files is an object from file names to texts (the names appear in diagnostics and in
// a graded submission's "file", as the command's paths do). Each call returns what the
// command prints on standard output; lastErrors() is what it printed on standard error and
// lastStatus() its exit code.
(function () {
  var calls = 0;
  var last = {out: '', errors: [], status: 0};

  function asFiles(input, defaultName) {
    if (typeof input === 'string') {
      var files = {};
      files[defaultName] = input;
      return files;
    }
    return input;
  }

  function writeAll(root, files) {
    Object.keys(files).forEach(function (name) {
      if (name.startsWith('/') || name.split('/').indexOf('..') >= 0) {
        throw new Error('raygrade: file name "' + name + '" must be relative, without ".."');
      }
      var parts = name.split('/');
      var folder = root;
      for (var i = 0; i + 1 < parts.length; ++i) {
        folder += '/' + parts[i];
        if (!FS.analyzePath(folder).exists) FS.mkdir(folder);
      }
      FS.writeFile(root + '/' + name, files[name]);
    });
  }

  function removeAll(path) {
    if (FS.isDir(FS.stat(path).mode)) {
      FS.readdir(path).forEach(function (entry) {
        if (entry !== '.' && entry !== '..') removeAll(path + '/' + entry);
      });
      FS.rmdir(path);
    } else {
      FS.unlink(path);
    }
  }

  // Writes the files into a fresh folder, runs `entry` there with relative names, cleans up.
  function run(files, entry) {
    var root = '/raygrade-' + (++calls);
    FS.mkdir(root);
    try {
      writeAll(root, files);
      FS.chdir(root);
      last = JSON.parse(entry());
    } finally {
      FS.chdir('/');
      removeAll(root);
    }
    return last.out;
  }

  function solveFormat(problems, format) {
    var files = asFiles(problems, 'problems.json');
    return run(files, function () {
      return Module.ccall('raygrade_solve', 'string', ['string', 'string'],
                          [JSON.stringify(Object.keys(files)), format]);
    });
  }

  // raygrade solve PROBLEMS --format json
  Module.solve = function (problems) { return solveFormat(problems, 'json'); };

  // raygrade solve PROBLEM --format FORMAT (json, md, html or txt)
  Module.solution = function (problem, format) {
    if (['json', 'md', 'html', 'txt'].indexOf(format) < 0) {
      throw new Error('raygrade: unknown format "' + format + '" (json, md, html, txt)');
    }
    return solveFormat(problem, format);
  };

  // raygrade grade --problems PROBLEMS --format json SUBMISSION; `submissionName` is the
  // submission's file name (default submission.json).
  Module.grade = function (problems, submission, submissionName) {
    var files = asFiles(problems, 'problems.json');
    var name = submissionName || 'submission.json';
    var all = Object.assign({}, files);
    if (Object.prototype.hasOwnProperty.call(all, name)) {
      throw new Error('raygrade: the submission\'s name "' + name + '" is a problem file\'s');
    }
    all[name] = submission;
    return run(all, function () {
      return Module.ccall('raygrade_grade', 'string', ['string', 'string'],
                          [JSON.stringify(Object.keys(files)), name]);
    });
  };

  // raygrade grade --assignment ASSIGNMENT --now NOW --format json SUBMISSION: `files` holds
  // the assignment file (named `assignment`) and its bank's files, at the places its "bank"
  // names; `now` is in seconds since 1970 UTC (default: this computer's clock). With
  // `cacheKey`, the assignment as read by the last call with the same key is used again (the
  // files must be the same): a Check then costs the grading alone.
  Module.gradeAssignment = function (files, assignment, submission, options) {
    options = options || {};
    Object.keys(options).forEach(function (key) {
      if (['now', 'submissionName', 'cacheKey'].indexOf(key) < 0) {
        throw new Error('raygrade: unknown option "' + key + '" (now, submissionName, cacheKey)');
      }
    });
    var name = options.submissionName || 'submission.json';
    var all = Object.assign({}, files);
    all[name] = submission;
    var now = options.now !== undefined ? options.now : Math.floor(Date.now() / 1000);
    return run(all, function () {
      return Module.ccall('raygrade_grade_assignment', 'string',
                          ['string', 'string', 'number', 'string'],
                          [assignment, name, now, options.cacheKey || '']);
    });
  };

  // raygrade solve ASSIGNMENT --student STUDENT --format FORMAT, or of one problem alone.
  Module.solveAssignment = function (files, assignment, student, format, problem) {
    return run(files, function () {
      return Module.ccall('raygrade_solve_assignment', 'string',
                          ['string', 'string', 'string', 'string'],
                          [assignment, student || '', format, problem || '']);
    });
  };

  Module.lastErrors = function () { return last.errors.slice(); };
  Module.lastStatus = function () { return last.status; };
})();
