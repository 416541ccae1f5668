// Starts `x3dcheck server` (the language server) for X3D XML, X3D JSON, ClassicVRML and
// VRML97 documents. Everything else (diagnostics, hover, completion, definitions,
// symbols, quick fixes) is the server's.

import * as vscode from "vscode";
import { findServer, INSTALL_HINT } from "./server";
import {
  LanguageClient,
  LanguageClientOptions,
  ServerOptions,
  TransportKind,
} from "vscode-languageclient/node";

let client: LanguageClient | undefined;

const LANGUAGES = ["x3d", "x3dj", "x3dv", "vrml"];

function settings() {
  const config = vscode.workspace.getConfiguration("x3dcheck");
  const level = config.get<string>("level") || undefined;
  const rulesDocUrl = config.get<string>("rulesDocUrl") || undefined;
  return { path: config.get<string>("path") || undefined, level, rulesDocUrl };
}

async function start(context: vscode.ExtensionContext): Promise<void> {
  const { path, level, rulesDocUrl } = settings();
  const found = await findServer(context.extensionPath, path);
  if (!found) {
    // Not awaited: activation does not wait for the user to dismiss the message.
    void vscode.window.showErrorMessage(INSTALL_HINT, "Open Settings").then((choice) => {
      if (choice === "Open Settings") {
        void vscode.commands.executeCommand("workbench.action.openSettings", "x3dcheck.path");
      }
    });
    return;
  }
  const serverOptions: ServerOptions = {
    command: found.command,
    args: ["server"],
    transport: TransportKind.stdio,
  };
  const clientOptions: LanguageClientOptions = {
    documentSelector: LANGUAGES.map((language) => ({ language })),
    initializationOptions: { level, rulesDocUrl },
    synchronize: { configurationSection: "x3dcheck" },
  };
  client = new LanguageClient("x3dcheck", "x3dcheck", serverOptions, clientOptions);
  context.subscriptions.push(client);
  try {
    await client.start();
  } catch (error) {
    vscode.window.showErrorMessage(
      `x3dcheck: could not start \`${found.command} server\` (from ${found.source}; set x3dcheck.path): ${error}`
    );
  }
}

export async function activate(context: vscode.ExtensionContext): Promise<void> {
  await start(context);
  // A new binary path needs a new server; other settings reach the running one.
  context.subscriptions.push(
    vscode.workspace.onDidChangeConfiguration(async (event) => {
      if (event.affectsConfiguration("x3dcheck.path")) {
        await client?.stop();
        await start(context);
      }
    })
  );
}

export async function deactivate(): Promise<void> {
  await client?.stop();
}
