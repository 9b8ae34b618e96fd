//! The floating-point work a piece of the bench executes, counted rather than estimated: the run
//! under valgrind's callgrind with one cost per machine instruction, each instruction's mnemonic
//! from objdump, and x86-64's scalar and packed double-precision arithmetic weighted by its flops
//! (a multiply-add 2, a packed operation one per lane). A hand count goes stale when the code
//! changes; this one cannot.

use std::collections::HashMap;
use std::process::Command;

/// Instructions and flops executed by `child_args` of the current executable, or why not counted.
pub fn count(child_args: &[String]) -> Result<(u64, u64), String> {
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let out = std::env::temp_dir().join(format!("pistonslap-flops-{}.callgrind", std::process::id()));
    let status = Command::new("valgrind")
        .args(["--tool=callgrind", "--dump-instr=yes", "--quiet"])
        .arg(format!("--callgrind-out-file={}", out.display()))
        .arg(&exe)
        .args(child_args)
        .status()
        .map_err(|e| format!("valgrind: {e}"))?;
    if !status.success() {
        return Err(format!("valgrind: {status}"));
    }
    let profile = std::fs::read_to_string(&out).map_err(|e| e.to_string());
    let _ = std::fs::remove_file(&out);
    let costs = instruction_costs(&profile?);
    let mut tables: HashMap<&str, HashMap<u64, String>> = HashMap::new();
    let (mut instructions, mut flops) = (0, 0);
    for ((object, address), n) in &costs {
        instructions += n;
        if !tables.contains_key(object.as_str()) {
            tables.insert(object, mnemonics(object)?);
        }
        flops += n * tables[object.as_str()].get(address).map_or(0, |m| flops_of(m));
    }
    Ok((instructions, flops))
}

/// Executions per (object, address) from a callgrind profile with `positions: instr line`.
fn instruction_costs(profile: &str) -> HashMap<(String, u64), u64> {
    // Objects are named once, at first mention (as `ob=` or `cob=`), then referred to by number.
    let mut names = HashMap::new();
    for line in profile.lines() {
        if let Some((id, name)) = line.strip_prefix("ob=").or_else(|| line.strip_prefix("cob=")).and_then(|r| r.split_once(' ')) {
            names.insert(id.to_string(), name.to_string());
        }
    }
    let (mut costs, mut object, mut address, mut call) = (HashMap::new(), String::new(), 0u64, false);
    for line in profile.lines() {
        if let Some(rest) = line.strip_prefix("ob=") {
            let id = rest.split(' ').next().unwrap_or_default();
            object = names.get(id).cloned().unwrap_or_default();
        } else if line.starts_with("calls=") {
            // The next cost line is the call's inclusive cost: it moves the position, counts nothing.
            call = true;
        } else if let [position, _, n, ..] = line.split_whitespace().collect::<Vec<_>>()[..] {
            address = match position.as_bytes()[0] {
                b'0' => u64::from_str_radix(position.trim_start_matches("0x"), 16).unwrap_or(address),
                b'+' => address + position[1..].parse::<u64>().unwrap_or(0),
                b'-' => address - position[1..].parse::<u64>().unwrap_or(0),
                b'*' => address,
                _ => continue,
            };
            if !std::mem::take(&mut call) {
                *costs.entry((object.clone(), address)).or_insert(0) += n.parse::<u64>().unwrap_or(0);
            }
        }
    }
    costs
}

/// Mnemonic and operands at each address of an object's code; none for a pseudo-object (`???`).
fn mnemonics(object: &str) -> Result<HashMap<u64, String>, String> {
    if !object.starts_with('/') {
        return Ok(HashMap::new());
    }
    let out = Command::new("objdump").args(["-d", "--no-show-raw-insn", object]).output().map_err(|e| format!("objdump: {e}"))?;
    let text = String::from_utf8_lossy(&out.stdout);
    Ok(text
        .lines()
        .filter_map(|line| {
            let (address, instruction) = line.split_once(":\t")?;
            Some((u64::from_str_radix(address.trim(), 16).ok()?, instruction.trim().to_string()))
        })
        .collect())
}

/// Double-precision flops of one x86-64 instruction (`mnemonic operands`).
fn flops_of(instruction: &str) -> u64 {
    let (mnemonic, operands) = instruction.split_once(char::is_whitespace).unwrap_or((instruction, ""));
    let m = mnemonic.strip_prefix('v').unwrap_or(mnemonic);
    let lanes = if m.ends_with("sd") {
        1
    } else if m.ends_with("pd") {
        if operands.contains("ymm") {
            4
        } else {
            2
        }
    } else {
        return 0;
    };
    let stem = &m[..m.len() - 2];
    let fused = ["fmadd", "fmsub", "fnmadd", "fnmsub"].iter().any(|f| stem.starts_with(f));
    if fused {
        2 * lanes
    } else if ["add", "sub", "mul", "div", "sqrt"].contains(&stem) {
        lanes
    } else {
        0
    }
}
