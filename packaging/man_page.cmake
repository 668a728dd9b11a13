# Writes the man page sedem.1 from `sedem --help` and `sedem COMMAND --help`, so that it
# never disagrees with the program. Run at build time:
#   cmake -DSEDEM=path/to/sedem -DVERSION=x.y.z -DOUT=sedem.1 -P man_page.cmake
set(commands run batch render reduce invert design bench)

function(help_of args var)
  execute_process(COMMAND ${SEDEM} ${args} --help OUTPUT_VARIABLE text RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${SEDEM} ${args} --help failed: ${status}")
  endif()
  # The program's own path in "Usage:" lines is just "sedem" in the page.
  string(REGEX REPLACE "Usage: [^ ]*sedem" "Usage: sedem" text "${text}")
  # roff: a leading '.' or '\'' would be a request; backslashes are escapes.
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "\n([.'])" "\n\\\\&\\1" text "${text}")
  set(${var} "${text}" PARENT_SCOPE)
endfunction()

help_of("" top)
set(page ".TH SEDEM 1 \"\" \"sedem ${VERSION}\" \"User Commands\"
.SH NAME
sedem \\- DEM simulation of the hydrometer, buoyancy-sphere and pipette sedimentation tests
.SH SYNOPSIS
.B sedem
.I COMMAND
[\\fIOPTIONS\\fR]
.SH DESCRIPTION
sedem simulates the laboratory sedimentation tests that measure the particle-size
distribution of fine soils with a Discrete Element Method model of every particle, reproduces
what each instrument reads and compares the resulting grading curve with the true one.
.PP
.nf
${top}
.fi
.SH COMMANDS
")
foreach(c ${commands})
  help_of("${c}" text)
  string(APPEND page ".SS sedem ${c}\n.nf\n${text}\n.fi\n")
endforeach()
string(APPEND page ".SH STUDIES ON A CLUSTER
\\fBsedem batch\\fR \\fB--emit slurm\\fR writes a batch's runs into \\fB--out\\fR DIR instead of
running them: each run's resolved scene (DIR/tasks/RUN.toml), a Slurm job array of one task
per run (DIR/sedem.sbatch; \\fB--slurm-time\\fR, \\fB--slurm-mem\\fR, \\fB--slurm-cpus\\fR,
\\fB--slurm-partition\\fR, \\fB--slurm-account\\fR) and DIR/submit.sh, which submits it and
then the summary as a job that waits for it. \\fB--emit parallel\\fR writes DIR/parallel.txt,
one command line per run for GNU \\fBparallel\\fR(1), and DIR/parallel.sh, whose options go to
parallel (\\fB--sshlogin\\fR spreads the runs over machines that see DIR at the same path).
\\fBsedem batch --gather\\fR DIR then writes the summary a local batch writes, listing the runs
that did not complete (exit status 2, or 5 when one failed). A task run again goes on where
its run stopped. See share/doc/sedem/docs/batch.md.
")
string(APPEND page ".SH EXIT STATUS
0 done; 1 bad command line; 2 scene or input missing or invalid; 3 output folder cannot be
written (or holds another run: see \\fB--overwrite\\fR); 4 writing failed during the run;
5 the simulation failed; 130 interrupted.
.SH FILES
.TP
.I share/sedem/scenes/
the paper's five samples, the demo and stress cases
.TP
.I share/doc/sedem/
the user guide (README.md, docs/)
.SH SEE ALSO
\\fBparaview\\fR(1), \\fBsbatch\\fR(1), \\fBparallel\\fR(1); the Python package \\fBsedem\\fR (share/doc/sedem/docs/python.md)
")
file(WRITE "${OUT}" "${page}")
