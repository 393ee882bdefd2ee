// The mouse through whichever input system the project uses (Project Settings > Player > Active
// Input Handling): the Input System package (com.unity.inputsystem) when it is active and installed,
// else the legacy Input Manager. Unity defines ENABLE_INPUT_SYSTEM and ENABLE_LEGACY_INPUT_MANAGER
// from that setting; this assembly (Hedge.HalfEdge.Unity.asmdef) defines HEDGE_INPUT_SYSTEM when the
// package is installed, and references it only then. With "Both", the Input System package is read.
// The samples (Click to split, Break on click) read their clicks here.
#if ENABLE_INPUT_SYSTEM && HEDGE_INPUT_SYSTEM
using UnityEngine.InputSystem;
#endif
using UnityEngine;

namespace Hedge.Unity
{
/// <summary>Mouse clicks from either input system.</summary>
public static class PointerInput
{
    /// <summary>The input system this build reads ("Input System package", "Input Manager", or "none").</summary>
#if ENABLE_INPUT_SYSTEM && HEDGE_INPUT_SYSTEM
    public static readonly string Source = "Input System package";
#elif ENABLE_LEGACY_INPUT_MANAGER
    public static readonly string Source = "Input Manager";
#else
    public static readonly string Source = "none";
#endif

    /// <summary>True if the mouse button (0 left, 1 right) went down this frame; position: the mouse in screen
    /// pixels.</summary>
    public static bool ButtonDown(int button, out Vector3 position)
    {
#if ENABLE_INPUT_SYSTEM && HEDGE_INPUT_SYSTEM
        Mouse mouse = Mouse.current;
        position = Vector3.zero;
        if (mouse == null) return false;  // no mouse connected
        bool down = button == 0 ? mouse.leftButton.wasPressedThisFrame : mouse.rightButton.wasPressedThisFrame;
        if (down) position = mouse.position.ReadValue();
        return down;
#elif ENABLE_LEGACY_INPUT_MANAGER
        position = Input.mousePosition;
        return Input.GetMouseButtonDown(button);
#else
        // Neither input system is enabled (or the Input System package is active but not installed):
        // nothing to read.
        position = Vector3.zero;
        return false;
#endif
    }
}
}
