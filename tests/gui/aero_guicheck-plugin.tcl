# aero GUI check: a Pd GUI plugin that measures what a help patch looks like
# when Pd draws it (run by tests/gui/check-help.sh, which puts this folder on
# Pd's path under Xvfb). It does nothing unless AERO_GUICHECK_OUT is set, so
# the folder can sit on a path without changing Pd for anyone else.
#
# For the first patch window that opens, and for every subpatch window it
# opens by clicking each [pd ...] box (as a user does, in run mode), it
# measures the drawn canvas items and writes one line per window to
# $AERO_GUICHECK_OUT/$AERO_GUICHECK_NAME.result:
#   ok   NAME[/SUB...] (N boxes, N cords) PNG
#   FAIL NAME[/SUB...] overlap: A / B; cord A -> B crosses C; ...
# then quits Pd. A window fails when two boxes (objects, messages, number
# boxes, comments, GUI bodies and their labels) overlap, a cord runs through
# a box other than the two it connects, text runs out of its own box, the
# content does not fit the window as it opens, or the window runs off the
# screen. Each window is saved as NAME[.SUB...].png (ImageMagick's import).
#
# Works from the items' tags: Pd 0.53 and 0.56 both tag a box's text
# {TAG ...} and its border {TAGR ...} (0.53 adds obj, msg or atom), an IEM
# GUI's items {PTR[_]BASE*|LABEL|...}, a patch cord {TAG cord}.

if {![info exists ::env(AERO_GUICHECK_OUT)]} { return }

namespace eval ::aero_guicheck {
    variable out $::env(AERO_GUICHECK_OUT)
    variable name "patch"
    if {[info exists ::env(AERO_GUICHECK_NAME)]} {
        variable name $::env(AERO_GUICHECK_NAME)
    }
    variable seen {}        ;# toplevels met so far (checked or not)
    variable lines {}       ;# result lines
    variable wake 0
    variable settle_ms 400  ;# after a window maps: let Pd finish drawing
}

proc ::aero_guicheck::sleep {ms} {
    variable wake
    after $ms [list set ::aero_guicheck::wake 1]
    vwait ::aero_guicheck::wake
}

proc ::aero_guicheck::patch_windows {} {
    set found {}
    foreach w [winfo children .] {
        if {[winfo class $w] eq "PatchWindow" && [winfo ismapped $w]
            && [info exists ::loaded($w)] && $::loaded($w)} {
            lappend found $w
        }
    }
    return $found
}

# wait (up to ms) for a patch window that was not there before
proc ::aero_guicheck::wait_new_window {ms} {
    variable seen
    for {set t 0} {$t < $ms} {incr t 100} {
        foreach w [patch_windows] {
            if {[lsearch -exact $seen $w] < 0} {
                lappend seen $w
                sleep $::aero_guicheck::settle_ms
                return $w
            }
        }
        sleep 100
    }
    return ""
}

proc ::aero_guicheck::short {text} {
    regsub -all {\s+} $text " " text
    set text [string trim $text]
    if {[string length $text] > 36} {
        set text "[string range $text 0 32]..."
    }
    return $text
}

proc ::aero_guicheck::rect_of_coords {coords} {
    set x1 1e9; set y1 1e9; set x2 -1e9; set y2 -1e9
    foreach {x y} $coords {
        if {$x < $x1} {set x1 $x}
        if {$x > $x2} {set x2 $x}
        if {$y < $y1} {set y1 $y}
        if {$y > $y2} {set y2 $y}
    }
    return [list $x1 $y1 $x2 $y2]
}

proc ::aero_guicheck::union {a b} {
    if {$a eq ""} {return $b}
    lassign $a ax1 ay1 ax2 ay2
    lassign $b bx1 by1 bx2 by2
    return [list [expr {min($ax1,$bx1)}] [expr {min($ay1,$by1)}] \
                [expr {max($ax2,$bx2)}] [expr {max($ay2,$by2)}]]
}

# The boxes of a canvas: a list of {kind name rect group}; kind is obj, msg,
# atom, comment, gui (an IEM GUI's body) or label (an IEM GUI's label);
# group ties a GUI's body and label together. Also the cords, and texts
# that run out of their box.
proc ::aero_guicheck::measure {c} {
    set texts {}           ;# tag -> {text bbox}
    array set border {}    ;# tag -> {kind rect}
    array set gui_body {}  ;# ptr -> rect
    set labels {}
    set cords {}
    foreach i [$c find all] {
        set type [$c type $i]
        set tags [$c gettags $i]
        set tag0 [lindex $tags 0]
        if {[lsearch -exact $tags cord] >= 0} {
            lappend cords [$c coords $i]
            continue
        }
        set ptr ""
        set role ""
        foreach t $tags {
            # every IEM item has PTR[_]OBJ too: the part is in another tag
            if {[regexp {^((?:0x)?[0-9a-f]+)_?([A-Z]+)[0-9]*$} $t -> p r]} {
                set ptr $p
                if {$r ne "OBJ"} {set role $r}
            }
        }
        if {$ptr ne ""} {
            if {$role eq "BASE"} {
                set r [rect_of_coords [$c coords $i]]
                if {[info exists gui_body($ptr)]} {
                    set gui_body($ptr) [union $gui_body($ptr) $r]
                } else {
                    set gui_body($ptr) $r
                }
            } elseif {$role eq "LABEL" && $type eq "text"} {
                set text [$c itemcget $i -text]
                set bb [$c bbox $i]
                if {[string trim $text] ne "" && $bb ne ""} {
                    lappend labels [list $ptr $text $bb]
                }
            }
            continue
        }
        if {$type eq "text"} {
            set bb [$c bbox $i]
            if {$bb ne ""} {
                lappend texts [list $tag0 [$c itemcget $i -text] $bb]
            }
        } elseif {[string match *R $tag0] && $type in {line polygon}} {
            # Pd 0.53 names the kind in the second tag; 0.56 does not, but
            # the outline tells: a rectangle, a message's flag, an atom's
            # cut corner
            set coords [$c coords $i]
            set kind [lindex $tags 1]
            if {$kind ni {obj msg atom}} {
                switch [llength $coords] {
                    14 {set kind msg}
                    12 {set kind atom}
                    default {set kind obj}
                }
            }
            set border([string range $tag0 0 end-1]) \
                [list $kind [rect_of_coords $coords]]
        }
    }
    set boxes {}
    set overflow {}
    foreach t $texts {
        lassign $t tag text bb
        if {[info exists border($tag)]} {
            lassign $border($tag) kind rect
            switch $kind {
                obj  {set label "\[[short $text]\]"}
                msg  {set label "msg([short $text])"}
                atom {set label "number([short $text])"}
            }
            lappend boxes [list $kind $label $rect $tag]
            lassign $bb tx1 ty1 tx2 ty2
            lassign $rect x1 y1 x2 y2
            # Tk's text bbox is 1 px larger than the glyphs on each side
            if {$tx2 - 1 > $x2 || $ty2 - 1 > $y2} {
                lappend overflow "$label: text runs out of its box"
            }
        } else {
            lappend boxes [list comment "\"[short $text]\"" $bb $tag]
        }
    }
    foreach ptr [array names gui_body] {
        lappend boxes [list gui "gui($ptr)" $gui_body($ptr) $ptr]
    }
    foreach l $labels {
        lassign $l ptr text bb
        lappend boxes [list label "label([short $text])" $bb $ptr]
    }
    # name GUI bodies by their label where they have one
    set named {}
    foreach b $boxes {
        lassign $b kind label rect group
        if {$kind eq "gui"} {
            foreach l $labels {
                if {[lindex $l 0] eq $group} {
                    set label "gui([short [lindex $l 1]])"
                }
            }
        }
        lappend named [list $kind $label $rect $group]
    }
    return [list $named $cords $overflow]
}

proc ::aero_guicheck::overlap {a b} {
    lassign $a ax1 ay1 ax2 ay2
    lassign $b bx1 by1 bx2 by2
    # more than a pixel each way: boxes that touch do not count
    return [expr {min($ax2,$bx2) - max($ax1,$bx1) > 1
               && min($ay2,$by2) - max($ay1,$by1) > 1}]
}

proc ::aero_guicheck::contains {rect x y {pad 2}} {
    lassign $rect x1 y1 x2 y2
    return [expr {$x >= $x1 - $pad && $x <= $x2 + $pad
               && $y >= $y1 - $pad && $y <= $y2 + $pad}]
}

# does the segment cross the inside of the rectangle (shrunk by a pixel)?
# Liang-Barsky clipping
proc ::aero_guicheck::segment_crosses {x1 y1 x2 y2 rect} {
    lassign $rect rx1 ry1 rx2 ry2
    set rx1 [expr {$rx1 + 1}]; set ry1 [expr {$ry1 + 1}]
    set rx2 [expr {$rx2 - 1}]; set ry2 [expr {$ry2 - 1}]
    if {$rx2 <= $rx1 || $ry2 <= $ry1} {return 0}
    set dx [expr {double($x2 - $x1)}]
    set dy [expr {double($y2 - $y1)}]
    set t0 0.0; set t1 1.0
    foreach {p q} [list [expr {-$dx}] [expr {$x1 - $rx1}] $dx [expr {$rx2 - $x1}] \
                       [expr {-$dy}] [expr {$y1 - $ry1}] $dy [expr {$ry2 - $y1}]] {
        if {$p == 0} {
            if {$q <= 0} {return 0}
        } else {
            set r [expr {$q / $p}]
            if {$p < 0} {
                if {$r > $t1} {return 0}
                if {$r > $t0} {set t0 $r}
            } else {
                if {$r < $t0} {return 0}
                if {$r < $t1} {set t1 $r}
            }
        }
    }
    return [expr {$t1 > $t0}]
}

# the box a cord leaves (its bottom edge holds the outlet) or enters (its
# top edge holds the inlet)
proc ::aero_guicheck::endpoint_box {boxes x y edge} {
    foreach b $boxes {
        lassign $b kind label rect group
        lassign $rect x1 y1 x2 y2
        set ey [expr {$edge eq "bottom" ? $y2 : $y1}]
        if {$kind in {obj msg atom gui} && abs($y - $ey) <= 2
            && $x >= $x1 - 2 && $x <= $x2 + 2} {
            return $b
        }
    }
    return ""
}

# wait until the window's size and its scrollbars have settled: Pd shows
# scrollbars from a Configure handler, and on a loaded machine the first
# one can run before the window has its final size
proc ::aero_guicheck::settle {w c} {
    set last ""
    for {set t 0} {$t < 5000} {incr t 250} {
        update
        catch {::pdtk_canvas::pdtk_canvas_getscroll $c}
        update
        set now [list [wm geometry $w] [winfo width $c] [winfo height $c] \
                     [$c bbox all] [llength [$c find all]]]
        if {$now eq $last} {return}
        set last $now
        sleep 250
    }
}

# check one window; returns the subpatch boxes to open: {name x y}
proc ::aero_guicheck::check_window {w label} {
    variable out
    variable lines
    set c [tkcanvas_name $w]
    raise $w
    settle $w $c
    lassign [measure $c] boxes cords problems
    set overlaps 0
    set crossings 0
    # overlaps (a GUI's label may sit on its own body)
    set n [llength $boxes]
    for {set i 0} {$i < $n} {incr i} {
        lassign [lindex $boxes $i] ki li ri gi
        for {set j [expr {$i + 1}]} {$j < $n} {incr j} {
            lassign [lindex $boxes $j] kj lj rj gj
            if {$gi eq $gj} {continue}
            if {[overlap $ri $rj]} {
                lappend problems "overlap: $li / $lj"
                incr overlaps
            }
        }
    }
    # cords through boxes other than the two they connect
    foreach coords $cords {
        set from [endpoint_box $boxes {*}[lrange $coords 0 1] bottom]
        set to [endpoint_box $boxes {*}[lrange $coords end-1 end] top]
        set own {}
        foreach e [list $from $to] {
            if {$e ne ""} {lappend own [lindex $e 3]}
        }
        set fromname [expr {$from eq "" ? "?" : [lindex $from 1]}]
        set toname [expr {$to eq "" ? "?" : [lindex $to 1]}]
        foreach b $boxes {
            lassign $b kind blabel rect group
            if {$group in $own} {continue}
            set hit 0
            for {set k 0} {$k + 3 < [llength $coords]} {incr k 2} {
                lassign [lrange $coords $k [expr {$k + 3}]] x1 y1 x2 y2
                if {[segment_crosses $x1 $y1 $x2 $y2 $rect]} {set hit 1}
            }
            if {$hit} {
                lappend problems "cord $fromname -> $toname crosses $blabel"
                incr crossings
            }
        }
    }
    # the content fits the window as it opens, the window fits the screen
    set cw [winfo width $c]
    set ch [winfo height $c]
    set all [$c bbox all]
    if {$all ne ""} {
        lassign $all x1 y1 x2 y2
        # bbox all is a pixel larger than the items on each side
        if {$x1 + 1 < 0 || $y1 + 1 < 0 || $x2 - 1 > $cw || $y2 - 1 > $ch} {
            lappend problems [format "content %d..%d x %d..%d does not fit the window (%dx%d)" \
                [expr {$x1 + 1}] [expr {$x2 - 1}] [expr {$y1 + 1}] [expr {$y2 - 1}] $cw $ch]
        }
    }
    set sw [winfo screenwidth $w]
    set sh [winfo screenheight $w]
    set right [expr {[winfo rootx $w] + [winfo width $w]}]
    set bottom [expr {[winfo rooty $w] + [winfo height $w]}]
    if {$right > $sw || $bottom > $sh} {
        lappend problems "window [wm geometry $w] runs off the ${sw}x${sh} screen"
    }
    # screenshot
    set png [file join $out "[string map {/ .} $label].png"]
    if {[catch {exec import -window [winfo id $c] $png} err]} {
        lappend problems "no screenshot: $err"
    }
    set summary "([llength $boxes] boxes, [llength $cords] cords) $png"
    if {[llength $problems] == 0} {
        lappend lines "ok   $label $summary"
    } else {
        # the same problem twice (two cords between the same boxes) once
        set counted {}
        foreach p $problems {
            if {[dict exists $counted $p]} {
                dict incr counted $p
            } else {
                dict set counted $p 1
            }
        }
        set said {}
        dict for {p n} $counted {
            lappend said [expr {$n > 1 ? "$p (x$n)" : $p}]
        }
        set others [expr {[llength $problems] - $overlaps - $crossings}]
        lappend lines "FAIL $label ($overlaps overlaps, $crossings crossings, $others other): [join $said { | }]"
    }
    # the subpatches it holds, to open next
    set subs {}
    foreach b $boxes {
        lassign $b kind blabel rect
        if {$kind eq "obj" && [regexp {^\[pd ([^\] ]+)} $blabel -> sub]} {
            lassign $rect x1 y1 x2 y2
            lappend subs [list $sub [expr {($x1 + $x2) / 2}] [expr {($y1 + $y2) / 2}]]
        }
    }
    return $subs
}

proc ::aero_guicheck::visit {w label} {
    variable lines
    foreach sub [check_window $w $label] {
        lassign $sub subname x y
        # a click in run mode opens a subpatch, as it does for a user
        pdsend "$w mouse $x $y 1 0"
        pdsend "$w mouseup $x $y 1"
        set sw [wait_new_window 5000]
        if {$sw eq ""} {
            lappend lines "FAIL $label/$subname did not open"
            continue
        }
        visit $sw $label/$subname
        pdsend "$sw menuclose 0"
        sleep 200
        raise $w
    }
}

proc ::aero_guicheck::run {} {
    variable out
    variable name
    variable lines
    catch {wm withdraw .pdwindow}
    set w [wait_new_window 30000]
    if {$w eq ""} {
        lappend lines "FAIL $name no patch window opened"
    } elseif {[catch {visit $w $name} err]} {
        lappend lines "FAIL $name check error: $err"
    }
    set f [open [file join $out "$name.result"] w]
    puts $f [join $lines "\n"]
    close $f
    pdsend "pd quit"
}

after idle ::aero_guicheck::run
