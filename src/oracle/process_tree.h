#pragma once
/// The end of every process a tested program started. lpvid makes itself a
/// child subreaper: a process the program detaches from its parent (setsid, a
/// double fork) is reparented to lpvid when that parent ends, not to init,
/// so lpvid still finds it. The program runs in a session of its own
/// (outside_command.h), and its processes stay outside lpvid's session (a
/// new session is the only one a process can move to): that tells them from
/// lpvid's own children, such as a solver run in a child process, which
/// share lpvid's session and are never touched here.

#include <string>
#include <vector>

namespace lpvid {

/// Makes this process a child subreaper (prctl PR_SET_CHILD_SUBREAPER) for
/// the rest of its life; "" when done, else the kernel's refusal in words.
std::string become_child_subreaper();

/// Kills (SIGKILL) and reaps every child of this process that is outside its
/// session, pass after pass until a pass finds none: a killed process's own
/// children are reparented to this one and found by the next pass. Those
/// that had ended already (zombies) are reaped quietly; the others are
/// returned as "pid (name)", in the order they were killed.
std::vector<std::string> end_processes_of_other_sessions();

}  // namespace lpvid
