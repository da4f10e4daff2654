#!/usr/bin/env bash
# The restrictions on scenes (README "Restrictions"), end to end: each
# forbidden read, write and shell-out is refused by default, and allowed by
# the option (or the frameray.conf line) that the refusal names.
#
#     run_restriction_test.sh FRAMERAY
set -uo pipefail
frameray="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/scenes" "$work/outside" "$work/out" "$work/home"
echo '42' > "$work/outside/data.txt"
echo '#declare FromOutside = 7;' > "$work/outside/outside.inc"
failures=0

# run EXPECT NAME SCENE-TEXT [OPTIONS...]: EXPECT is "ok" or "refused".
run() {
    local expect="$1" name="$2" text="$3"
    shift 3
    printf '#version 3.7;\nglobal_settings { assumed_gamma 1 }\n%s\nsphere { 0, 1 pigment { rgb 1 } }\n' "$text" \
        > "$work/scenes/$name.pov"
    (cd "$work/scenes" && env -u POVINI -u POVRAYOPT -u XDG_CONFIG_HOME HOME="$work/home" ${CONFIG:+XDG_CONFIG_HOME="$CONFIG"} \
        "$frameray" "$name.pov" +W8 +H8 -D -GR -GS "+O$work/out/$name.png" "$@" > "$work/stdout" 2> "$work/stderr")
    local status=$?
    if [ "$expect" = ok ] && [ $status -ne 0 ]; then
        echo "restrictions: $name: expected success, got exit status $status:" >&2
        cat "$work/stderr" >&2
        failures=$((failures + 1))
    elif [ "$expect" = refused ] && { [ $status -eq 0 ] || [ $status -ge 128 ] || ! grep -q "not allowed\|is refused" "$work/stderr"; }; then
        echo "restrictions: $name: expected a refusal, got exit status $status:" >&2
        cat "$work/stderr" >&2
        failures=$((failures + 1))
    else
        echo "restrictions: $name: $expect"
    fi
}
check_file() {  # check_file yes|no PATH WHAT
    if [ "$1" = yes ] && [ ! -e "$2" ]; then
        echo "restrictions: $3: $2 was not written" >&2
        failures=$((failures + 1))
    elif [ "$1" = no ] && [ -e "$2" ]; then
        echo "restrictions: $3: $2 was written although refused" >&2
        failures=$((failures + 1))
    fi
}

# Writing outside the scene's, working and output folders.
write_outside="#fopen F \"$work/outside/w.txt\" write #write (F, \"x\") #fclose F"
run refused write_outside "$write_outside"
check_file no "$work/outside/w.txt" write_outside
run ok write_outside_allowed "$write_outside" "Write_Path=$work/outside"
check_file yes "$work/outside/w.txt" write_outside_allowed

# Writing through '..'.
write_up='#fopen F "../up.txt" write #write (F, "x") #fclose F'
run refused write_parent "$write_up"
check_file no "$work/up.txt" write_parent
run ok write_parent_allowed "$write_up" "Write_Path=$work"
check_file yes "$work/up.txt" write_parent_allowed

# Writing into the output folder and the scene's folder is fine.
run ok write_output_folder "#fopen F \"$work/out/state.txt\" write #fclose F"
run ok write_scene_folder '#fopen F "state.txt" write #write (F, "1") #fclose F #fopen G "state.txt" read #read (G, V)'

# Reading /etc/passwd with #fopen, and an include outside.
read_passwd='#fopen F "/etc/passwd" read #fclose F'
run refused read_passwd "$read_passwd"
run ok read_passwd_read_path "$read_passwd" "Read_Path=/etc"
run ok read_passwd_no_restrictions "$read_passwd" "File_Restrictions=off"
include_outside="#include \"$work/outside/outside.inc\" #if (FromOutside != 7) #error \"wrong value\" #end"
run refused include_outside "$include_outside"
run ok include_outside_allowed "$include_outside" "Read_Path=$work/outside"
# A folder allowed for writing may be read back.
run ok read_from_write_path "#fopen F \"$work/outside/data.txt\" read #read (F, V)" "Write_Path=$work/outside"
# file_exists() does not reveal files the scene may not read.
run ok file_exists_hidden '#if (file_exists("/etc/passwd")) #error "file_exists saw /etc/passwd" #end'

# An image map outside the allowed folders (the image made by frameray).
(cd "$work" && "$frameray" "$work/scenes/read_passwd_read_path.pov" +W4 +H4 -D -GA "+O$work/outside/img.png" Read_Path=/etc)
image_map="plane { z, 2 pigment { image_map { png \"$work/outside/img.png\" } } }"
run refused image_outside "$image_map"
run ok image_outside_allowed "$image_map" "Read_Path=$work/outside"

# Shell commands.
run refused shell_command '' "Pre_Frame_Command=touch $work/ran"
check_file no "$work/ran" shell_command
run ok shell_command_allowed '' "Pre_Frame_Command=touch $work/ran" "Allow_Shell_Commands=on"
check_file yes "$work/ran" shell_command_allowed

# frameray.conf widens the restrictions too.
mkdir -p "$work/config/frameray"
printf '; the user policy\nRead_Path=/etc\nAllow_Shell_Commands=on\n' > "$work/config/frameray/frameray.conf"
CONFIG="$work/config" run ok config_read_path "$read_passwd" "Post_Scene_Command=touch $work/ran2"
check_file yes "$work/ran2" config_read_path

# The trust rule: an INI file beside the scene is as untrusted as the scene;
# the same options on the command line are the user's own.
printf 'Library_Path=%s\n' "$work/outside" > "$work/scenes/lib.ini"
run refused ini_library_path '#include "outside.inc"' lib.ini
run ok library_path_command_line '#include "outside.inc"' "Library_Path=$work/outside"
printf 'Output_File_Name=%s/\n' "$work/outside/frames" > "$work/scenes/out.ini"
run refused ini_output_folder '' out.ini
check_file no "$work/outside/frames" ini_output_folder
printf 'Debug_File=%s\n' "$work/outside/debug.txt" > "$work/scenes/debug.ini"
run refused ini_debug_file '#debug "written"' debug.ini
check_file no "$work/outside/debug.txt" ini_debug_file
printf 'Create_Ini=%s\n' "$work/outside/created.ini" > "$work/scenes/create.ini"
run refused ini_create_ini '' create.ini
check_file no "$work/outside/created.ini" ini_create_ini
printf 'Width=6\nHeight=4\nOutput_File_Name=frames/\nDebug_File=debug.txt\n' > "$work/scenes/inside.ini"
run ok ini_inside_its_folder '#debug "written"' inside.ini
check_file yes "$work/scenes/frames/ini_inside_its_folder.png" ini_inside_its_folder
check_file yes "$work/scenes/debug.txt" ini_inside_its_folder

# An output name whose folder does not exist is refused (povray refuses it
# too); a name ending in '/' is a folder, created.
run_plain() {  # run_plain NAME OPTIONS...: the status and stderr of a run
    local name="$1"
    shift
    printf '#version 3.7;\nsphere { 0, 1 pigment { rgb 1 } }\n' > "$work/scenes/$name.pov"
    (cd "$work/scenes" && env -u POVINI -u POVRAYOPT -u XDG_CONFIG_HOME HOME="$work/home" \
        "$frameray" "$name.pov" +W8 +H8 -D -GR -GS "$@" > "$work/stdout" 2> "$work/stderr")
}
run_plain missing_folder "+O$work/no/such/dir/x.png"
status=$?
if [ $status -ne 2 ] || ! grep -q "does not exist" "$work/stderr" || [ -e "$work/no" ]; then
    echo "restrictions: missing_folder: expected a refusal without creating folders (status $status):" >&2
    cat "$work/stderr" >&2
    failures=$((failures + 1))
else
    echo "restrictions: missing_folder: refused"
fi
run_plain created_folder "+O$work/made/here/" || { echo "restrictions: created_folder failed" >&2; failures=$((failures + 1)); }
check_file yes "$work/made/here/created_folder.png" created_folder

# Symbolic links planted where frameray writes (a scene folder unpacked
# from a stranger's archive) are replaced or refused, never written
# through: the frame log, the journal, a stream file, Create_Ini.
echo 'precious' > "$work/outside/precious.txt"
mkdir -p "$work/linked"
ln -s "$work/outside/precious.txt" "$work/linked/links.log"
ln -s "$work/outside/precious.txt" "$work/linked/.links.frameray-journal"
ln -s "$work/outside/precious.txt" "$work/scenes/debug.out"
ln -s "$work/outside/precious.txt" "$work/scenes/created.ini"
printf '#version 3.7;\n#debug "scene text"\nsphere { 0, 1 pigment { rgb 1 } }\n' > "$work/scenes/links.pov"
(cd "$work/scenes" && env -u POVINI -u POVRAYOPT -u XDG_CONFIG_HOME HOME="$work/home" \
    "$frameray" links.pov +W8 +H8 -D -GR -GS "+O$work/linked/" > "$work/stdout" 2> "$work/stderr")
if [ "$(cat "$work/outside/precious.txt")" != precious ] || [ -L "$work/linked/links.log" ] ||
    [ -L "$work/linked/.links.frameray-journal" ]; then
    echo "restrictions: links: the log or journal was written through a link" >&2
    cat "$work/stderr" >&2
    failures=$((failures + 1))
else
    echo "restrictions: links: log and journal replace the links"
fi
for option in Debug_File=on Create_Ini=created.ini; do
    (cd "$work/scenes" && env -u POVINI -u POVRAYOPT -u XDG_CONFIG_HOME HOME="$work/home" \
        "$frameray" links.pov +W8 +H8 -D -GR -GS "+O$work/linked/" "$option" > "$work/stdout" 2> "$work/stderr")
    status=$?
    if [ "$(cat "$work/outside/precious.txt")" != precious ] ||
        { [ $status -ne 0 ] && ! grep -q "symbolic link" "$work/stderr"; }; then
        echo "restrictions: links: $option wrote through a link (status $status)" >&2
        cat "$work/stderr" >&2
        failures=$((failures + 1))
    else
        echo "restrictions: links: $option does not follow the link"
    fi
done

# Shell commands: %o and %s are quoted for /bin/sh, so an output name
# holding $(...) is a name, not a command.
mkdir -p "$work/quoting"
printf '#version 3.7;\nsphere { 0, 1 pigment { rgb 1 } }\n' > "$work/quoting/q.pov"
(cd "$work/quoting" && env -u POVINI -u POVRAYOPT -u XDG_CONFIG_HOME HOME="$work/home" \
    "$frameray" q.pov +W8 +H8 -D -GR -GS 'Output_File_Name=y$(touch injected).png' \
    Allow_Shell_Commands=on 'Post_Frame_Command=ls -l %o > listed.txt' > "$work/stdout" 2> "$work/stderr")
if [ -e "$work/quoting/injected" ] || ! grep -q 'y\$(touch injected).png' "$work/quoting/listed.txt"; then
    echo "restrictions: quoting: the output name ran as a command" >&2
    cat "$work/stderr" >&2
    failures=$((failures + 1))
else
    echo "restrictions: quoting: %o is quoted"
fi

if [ $failures -ne 0 ]; then
    echo "restrictions: $failures check(s) failed" >&2
    exit 1
fi
echo "restrictions: all checks passed"
